// fsi-surface-query: the geometry engine of the Python post-processing, on a pipe
// (QueryServer.hpp has the protocol; python/fsi/surface_engine.py is its client).
//   fsi-surface-query          answers requests on stdin, replies on stdout
// Exit codes: 0 at "quit" or the end of the input, 1 when the pipe is out of step.

#include "apps/fsi-surface-query/QueryServer.hpp"
#include "common/ExitCodes.hpp"
#include "common/GuardedMain.hpp"

#include <cstdio>

int main(int argc, char **) {
  return fsi::common::guarded_main("fsi-surface-query", [&] {
    if (argc > 1) {
      std::fputs("usage: fsi-surface-query   (requests on stdin: see apps/fsi-surface-query/QueryServer.hpp)\n",
                 stderr);
      return fsi::common::exit_code_bad_input;
    }
    fsi::apps::QueryServer(stdin, stdout).serve();
    return fsi::common::exit_code_success;
  });
}
