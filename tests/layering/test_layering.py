#!/usr/bin/python3
"""scripts/check_layering.py: the tree's includes and CMake links all point down the layering,
with no file exempt, and the check names the offending line when one does not (in a copy of the
tree: an upward include, a sideways include between two physics modules, a main.cpp in a module,
one executable's file included by another, an upward link)."""

import glob
import os
import re
import shutil
import subprocess
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
CHECK = os.path.join(ROOT, "scripts", "check_layering.py")
MODULES = ["apps", "case", "structure_solver", "coupler", "prescribed_flow", "fluid_adapter", "pump", "participant", "proto",
           "geometry", "hdf5", "checkpoint", "motion", "common"]


def check(root):
    return subprocess.run(["/usr/bin/python3", CHECK, root], capture_output=True, text=True)


def append_line(path, line):
    with open(path) as f:
        lines = f.read().splitlines()
    lines.append(line)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return len(lines)


CASES = ["copy-up", "copy-side", "copy-main", "copy-apps", "copy-link"]  # the copies the tests make, one each


def copy_of(tmp, name):
    tree = os.path.join(tmp, name)
    shutil.copytree(tmp, tree, ignore=shutil.ignore_patterns(*CASES))
    return tree


DOCUMENTED_FOLDERS = set(MODULES) | {"tests", "bench", "scripts", "python", "cases", "docs", "cmake"}


def documented_paths(text):
    """Backticked repository paths (`folder/...`) whose first folder is one of the tree's."""
    for match in re.finditer(r"`([A-Za-z0-9_.-]+(?:/[A-Za-z0-9_.-]+)+)`", text):
        path = match.group(1)
        if path.split("/")[0] in DOCUMENTED_FOLDERS:
            yield path


class DocumentedPaths(unittest.TestCase):
    def test_the_docs_name_files_that_exist(self):
        """docs/model.md maps each equation to its file and test; a moved file must not leave
        the docs pointing at nothing (nor the README, docs/layout.md, the case READMEs)."""
        docs = [os.path.join(ROOT, "README.md")] + glob.glob(os.path.join(ROOT, "docs", "*.md")) + \
            glob.glob(os.path.join(ROOT, "cases", "*", "README.md"))
        missing = []
        for doc in docs:
            with open(doc) as f:
                for path in documented_paths(f.read()):
                    if not os.path.exists(os.path.join(ROOT, path)):
                        missing.append(f"{os.path.relpath(doc, ROOT)}: `{path}`")
        self.assertEqual(missing, [], "paths in the docs that do not exist:\n" + "\n".join(missing))


class QuotedReferences(unittest.TestCase):
    def test_the_docs_quote_each_self_measured_reference_as_written(self):
        """cases/<case>/reference.yaml holds a case's self-measured values once, with their
        provenance; every file in its quoted_in list must hold each value as written there."""
        try:
            import yaml
        except ImportError:
            self.skipTest("python3-yaml is not installed")
        files = glob.glob(os.path.join(ROOT, "cases", "*", "reference.yaml"))
        self.assertGreaterEqual(len(files), 2)
        missing = []
        for path in files:
            with open(path) as f:
                ref = yaml.load(f, Loader=yaml.BaseLoader)  # every value as the text written
            for doc in ref["quoted_in"]:
                with open(os.path.join(ROOT, doc)) as f:
                    text = f.read()
                for preset, values in ref.items():
                    if preset in ("provenance", "quoted_in"):
                        continue
                    missing += [f"{doc}: {preset} {key} = {value} ({os.path.relpath(path, ROOT)})"
                                for key, value in values.items() if value not in text]
        self.assertEqual(missing, [], "values of reference.yaml the docs do not quote:\n" + "\n".join(missing))


class SolverLinks(unittest.TestCase):
    def test_only_the_structure_process_links_the_structure_solver(self):
        """The case reads the structures' configuration (fsi_structure_config) and builds no
        model: the case, the coupler and the fluids do not link the solver (fsi_structure)."""
        import importlib.util
        spec = importlib.util.spec_from_file_location("check_layering", CHECK)
        layering = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(layering)
        for target in ["fsi_case", "fsi-coupler", "fsi-prescribed-flow", "fsi-openfoam-fluid"]:
            closure = layering.link_closure(ROOT, target)
            self.assertIn("fsi_structure_config", closure, target)
            self.assertNotIn("fsi_structure", closure, target)
        self.assertIn("fsi_structure", layering.link_closure(ROOT, "fsi-structure"))


def load_script(name):
    import importlib.util
    spec = importlib.util.spec_from_file_location(name, os.path.join(ROOT, "scripts", name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class FunctionLengths(unittest.TestCase):
    """The run loops stay readable: no function of the participant runtime, the coupler or the
    OpenFOAM solver over 60 lines, no participant handler (a request of the coupler answered)
    over 25 (scripts/function_lengths.py)."""

    def test_no_function_of_the_run_loops_is_over_60_lines(self):
        lengths = load_script("function_lengths")
        long = [(path, name, n) for folder in ["participant", "coupler", "fluid_adapter/solver"]
                for path in lengths.sources([os.path.join(ROOT, folder)])
                for name, _, n in lengths.function_lengths(path) if n > 60]
        self.assertEqual(long, [])

    def test_no_participant_handler_is_over_25_lines(self):
        lengths = load_script("function_lengths")
        handlers = 0
        for path in glob.glob(os.path.join(ROOT, "participant", "*Participant.cpp")):
            with open(path) as f:
                names = re.findall(r"\bon\(proto::Envelope::k\w+, \"\w+\", \[this\]\(const auto &m\) \{ (\w+)\(m\); \}\)",
                                   f.read())
            cls = os.path.basename(path)[:-4]
            measured = {name.split("::")[-1]: n for name, _, n in lengths.function_lengths(path)
                        if name.startswith(cls + "::")}
            for name in names:
                handlers += 1
                self.assertLessEqual(measured[name], 25, "%s::%s" % (cls, name))
        self.assertEqual(handlers, 3)  # InterpolateRequest, FluidAdvance, StructureAdvance

    def test_the_measure_counts_a_definition_from_its_signature_to_its_closing_brace(self):
        lengths = load_script("function_lengths")
        path = os.path.join(tempfile.mkdtemp(prefix="fsi-lengths-"), "f.cpp")
        with open(path, "w") as f:
            f.write("namespace a {\nint f();\nA::A(int x)\n    : x_(x) {}\n\nvoid A::g(int y) {\n  if (y) {\n"
                    "    h(\"}\");\n  }\n}\n} // namespace a\n")
        self.assertEqual(lengths.function_lengths(path), [("A::A", 3, 2), ("A::g", 6, 5)])
        shutil.rmtree(os.path.dirname(path))


class Layering(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="fsi-layering-")
        for module in MODULES:
            shutil.copytree(os.path.join(ROOT, module), os.path.join(cls.tmp, module),
                            ignore=shutil.ignore_patterns("*.md", "*.proto", "*.py", "*.yaml", "designs"))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def test_every_include_of_the_tree_points_down(self):
        result = check(ROOT)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertEqual(result.stdout, "")

    def test_an_upward_include_is_refused_with_its_file_and_line(self):
        tree = copy_of(self.tmp, "copy-up")
        line = append_line(os.path.join(tree, "common", "Types.hpp"), '#include "structure_solver/Scene.hpp"')
        result = check(tree)
        self.assertEqual(result.returncode, 1)
        self.assertIn(f'common/Types.hpp:{line}: #include "structure_solver/Scene.hpp"', result.stdout)
        self.assertEqual(len(result.stdout.splitlines()), 1, result.stdout)

    def test_a_sideways_include_between_physics_modules_is_refused(self):
        tree = copy_of(self.tmp, "copy-side")
        line = append_line(os.path.join(tree, "coupler", "CouplingRun.cpp"), '#include "case/CaseConfig.hpp"')
        line2 = append_line(os.path.join(tree, "fluid_adapter", "Precursor.cpp"), '#include "coupler/CouplingRun.hpp"')
        result = check(tree)
        self.assertEqual(result.returncode, 1)
        self.assertIn(f"coupler/CouplingRun.cpp:{line}:", result.stdout)
        self.assertIn(f"fluid_adapter/Precursor.cpp:{line2}:", result.stdout)
        self.assertIn("may not include physics module coupler", result.stdout)

    def test_a_main_in_a_module_is_not_exempt(self):
        """The mains live in apps/: one put back in a module is checked like any of its files."""
        tree = copy_of(self.tmp, "copy-main")
        with open(os.path.join(tree, "coupler", "main.cpp"), "w") as f:
            f.write('#include "CouplingRun.hpp"\n#include "case/CaseOptions.hpp"\nint main() { return 0; }\n')
        result = check(tree)
        self.assertEqual(result.returncode, 1)
        self.assertIn('coupler/main.cpp:2: #include "case/CaseOptions.hpp": the physics module coupler may not '
                      'include case', result.stdout)
        self.assertEqual(len(result.stdout.splitlines()), 1, result.stdout)

    def test_an_executable_does_not_include_another_executables_files(self):
        tree = copy_of(self.tmp, "copy-apps")
        line = append_line(os.path.join(tree, "apps", "fsi-coupler", "main.cpp"),
                           '#include "apps/fsi-openfoam-fluid/SelfLaunch.hpp"')
        result = check(tree)
        self.assertEqual(result.returncode, 1)
        self.assertIn(f"apps/fsi-coupler/main.cpp:{line}: #include \"apps/fsi-openfoam-fluid/SelfLaunch.hpp\": the "
                      "executable apps/fsi-coupler may not include executable apps/fsi-openfoam-fluid", result.stdout)

    def test_an_upward_link_is_refused_with_its_file_and_line(self):
        """The CMake link lines are read too: a foundation linking a physics module's library is
        refused as its include would be, and so is a physics module linking the case."""
        tree = copy_of(self.tmp, "copy-link")
        line = append_line(os.path.join(tree, "hdf5", "CMakeLists.txt"), "target_link_libraries(fsi_hdf5 PUBLIC fsi_structure)")
        line2 = append_line(os.path.join(tree, "coupler", "CMakeLists.txt"),
                            "target_link_libraries(fsi_coupler PRIVATE\n  fsi_case)")
        result = check(tree)
        self.assertEqual(result.returncode, 1)
        self.assertIn(f"hdf5/CMakeLists.txt:{line}: fsi_hdf5 links fsi_structure: the foundation hdf5 may not link "
                      "physics module structure_solver", result.stdout)
        self.assertIn(f"coupler/CMakeLists.txt:{line2}: fsi_coupler links fsi_case: the physics module coupler "
                      "may not link case", result.stdout)
        self.assertEqual(len(result.stdout.splitlines()), 2, result.stdout)


if __name__ == "__main__":
    unittest.main(verbosity=2)
