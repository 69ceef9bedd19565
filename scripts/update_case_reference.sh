#!/usr/bin/env bash
# Regenerates the case-file reference in docs/case-reference.md (between the case-reference
# markers) from the declarations the parser uses (`fsi-structure --schema`). The test
# RunBehaviour.CaseReferenceDocHoldsTheGeneratedSchema fails when it is stale.
# Usage: scripts/update_case_reference.sh [PATH_TO_fsi-structure]   (default: build/bin/fsi-structure)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BIN=${1:-$ROOT/build/bin/fsi-structure}
schema=$(mktemp)
"$BIN" --schema >"$schema"
/usr/bin/python3 - "$ROOT/docs/case-reference.md" "$schema" <<'PY'
import sys
doc_path, schema_path = sys.argv[1], sys.argv[2]
begin, end = "<!-- case-reference:begin -->\n", "<!-- case-reference:end -->"
text = open(doc_path).read()
head, rest = text.split(begin, 1)
_, tail = rest.split(end, 1)
open(doc_path, "w").write(head + begin + open(schema_path).read() + end + tail)
PY
rm -f "$schema"
