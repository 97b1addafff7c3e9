"""Runs the code blocks of the project's documentation, so that an example that stops working
fails the suite: README.md, CHANGELOG.md and every page of Documentation/.

Each fenced block's language says what happens to it; an HTML comment on the line before the
fence (`<!-- docs-test: WORD -->`) can say more:

- `python`: run as a script by this interpreter, the package importable, in a scratch folder
  that holds `cloud.vdb` (a small OpenVDB cloud) where the build has OpenVDB. It must exit with 0
  and print no VTK error, and every PNG it writes must show a drawn volume
  (Testing/Scripts/CheckPicture.py). `continue`: the page's previous Python blocks run first, in
  the same script. `pvbatch`: a ParaView script, run by pvbatch with the plugin's path as its
  first argument (only with --pvbatch: the plugin's build runs those). A block that imports
  pyvista runs where PyVista is installed (Debian 13 and later).
- `cpp` with a `cmake` block on the same page: a project built against the installed package
  (--installed, the prefix Install.Package installs and moves) and run.
- `sh`: `run`: run by bash in a scratch folder where `build` is the build folder and the
  repository's folders are linked. Otherwise (builds, benchmarks, long runs) it must parse
  (`bash -n`), every `./avs` command must be one the driver knows, every `build/bin/PROGRAM` must
  have been built and every `--option` after it must be one the program knows (its name is in
  the program), and every repository path it names must exist.
- `text`: output shown for reading; not run.

Every relative link and picture of the pages (and of ARCHITECTURE.md) must point at a file.

Any other language is an error, so that no block goes untested by accident.

Usage: TestDocs.py --root REPO --build BUILD [--installed PREFIX] [--cloud FILE]
                   [--linker-flags FLAGS] [--pvbatch PVBATCH --plugin PLUGIN] [--keep DIR]
"""
import argparse
import glob
import importlib.util
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

FENCE = re.compile(r"^```(\S*)\s*$")
MARK = re.compile(r"^<!--\s*docs-test:\s*(\w[\w-]*)\s*-->\s*$")
REPOSITORY_FOLDERS = ("Data", "Documentation", "Examples", "IO", "Module", "ParaView", "Rendering",
                      "Testing", "Utilities")


class Block:
    def __init__(self, page, line, language, mark, text):
        self.page, self.line, self.language, self.mark, self.text = page, line, language, mark, text

    def where(self):
        return f"{self.page}:{self.line} ({self.language or 'no language'})"


def pages_of(root, *front):
    """The front pages named that exist, then every page of Documentation/."""
    pages = [os.path.join(root, name) for name in front]
    pages += sorted(glob.glob(os.path.join(root, "Documentation", "**", "*.md"), recursive=True))
    return [page for page in pages if os.path.exists(page)]


def read_blocks(root):
    blocks = []
    for page in pages_of(root, "README.md", "CHANGELOG.md"):
        with open(page, encoding="utf-8") as f:
            lines = f.read().split("\n")
        name = os.path.relpath(page, root)
        i = 0
        while i < len(lines):
            opening = FENCE.match(lines[i])
            if not opening:
                i += 1
                continue
            marked = MARK.match(lines[i - 1]) if i > 0 else None
            mark = marked.group(1) if marked else None
            end = i + 1
            while end < len(lines) and lines[end].rstrip() != "```":
                end += 1
            if end == len(lines):
                raise SystemExit(f"{name}:{i + 1}: a code block is not closed")
            blocks.append(Block(name, i + 1, opening.group(1), mark, "\n".join(lines[i + 1:end])))
            i = end + 1
    return blocks


def check_links(root, failures):
    """Every relative link and picture of the pages must point at a file of the repository."""
    for page in pages_of(root, "README.md", "CHANGELOG.md", "ARCHITECTURE.md"):
        with open(page, encoding="utf-8") as f:
            text = f.read()
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                continue
            path = os.path.normpath(os.path.join(os.path.dirname(page), target.split("#")[0]))
            if not os.path.exists(path):
                failures.append(f"{os.path.relpath(page, root)}: a link to {target}, which does "
                                "not exist")


def pictures_in(folder):
    """The PNG files under folder, without following links (a shell block's folder links the
    build folder, which may hold the folder itself)."""
    found = set()
    for directory, _, files in os.walk(folder):
        found.update(os.path.join(directory, name) for name in files if name.endswith(".png"))
    return found


def check_pictures(folder, before, failures, where):
    checker = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "Scripts",
                           "CheckPicture.py")
    for png in sorted(pictures_in(folder)):
        if png in before:
            continue
        result = subprocess.run([sys.executable, checker, png], capture_output=True, text=True)
        if result.returncode != 0:
            failures.append(f"{where}: {os.path.basename(png)}: {result.stdout}{result.stderr}")


def run_checked(command, cwd, env, where, failures, timeout=600):
    before = pictures_in(cwd)
    try:
        result = subprocess.run(command, cwd=cwd, env=env, capture_output=True, text=True,
                                timeout=timeout)
    except subprocess.TimeoutExpired:
        failures.append(f"{where}: did not finish in {timeout} s")
        return
    output = result.stdout + result.stderr
    if result.returncode != 0:
        failures.append(f"{where}: exit status {result.returncode}\n{output[-3000:]}")
        return
    if re.search(r"^(ERROR|Generic Warning|ERROR:)", output, re.M) or "vtkErrorMacro" in output:
        failures.append(f"{where}: printed an error\n{output[-3000:]}")
        return
    check_pictures(cwd, before, failures, where)
    print(f"ok: {where}")


def run_python(block, chain, args, scratch, env, failures):
    code = "\n\n".join([b.text for b in chain] + [block.text])
    if re.search(r"^\s*(import pyvista|from pyvista)", code, re.M) and \
            importlib.util.find_spec("pyvista") is None:
        print(f"skipped (no PyVista on this platform): {block.where()}")
        return
    if "cloud.vdb" in code and not os.path.exists(os.path.join(scratch, "cloud.vdb")):
        print(f"skipped (no OpenVDB in this build): {block.where()}")
        return
    script = os.path.join(scratch, f"block_{block.line}.py")
    with open(script, "w", encoding="utf-8") as f:
        f.write(code + "\n")
    run_checked([sys.executable, script], scratch, env, block.where(), failures)


def run_pvbatch(block, args, scratch, env, failures):
    script = os.path.join(scratch, f"pvblock_{block.line}.py")
    with open(script, "w", encoding="utf-8") as f:
        f.write(block.text + "\n")
    run_checked([args.pvbatch, "--force-offscreen-rendering", script, args.plugin], scratch, env,
                block.where(), failures)


def build_cxx(page, cmake, sources, args, scratch, env, failures):
    where = f"{page}: the C++ quick start"
    if not args.installed:
        failures.append(f"{where}: no installed package given (--installed)")
        return
    project = os.path.join(scratch, "cxx-" + re.sub(r"[^A-Za-z0-9]+", "-", page))
    os.makedirs(project, exist_ok=True)
    with open(os.path.join(project, "CMakeLists.txt"), "w", encoding="utf-8") as f:
        f.write(cmake.text + "\n")
    names = re.findall(r"add_executable\(\s*\S+\s+([^)]+)\)", cmake.text)
    files = names[0].split() if names else []
    if len(files) != len(sources):
        failures.append(f"{where}: the CMake block names {files}, the page has {len(sources)} "
                        "C++ blocks")
        return
    for name, source in zip(files, sources):
        with open(os.path.join(project, name), "w", encoding="utf-8") as f:
            f.write(source.text + "\n")
    options = ["-DCMAKE_BUILD_TYPE=Release", f"-DCMAKE_PREFIX_PATH={args.installed}"]
    if args.linker_flags:
        options.append(f"-DCMAKE_EXE_LINKER_FLAGS={args.linker_flags}")
    binary = os.path.join(project, "build")
    # (The compiler and CMake run without the sanitizer runtime that the Python tests preload; a
    # program built with the sanitizers brings its own.)
    env = {key: value for key, value in env.items() if key != "LD_PRELOAD"}
    for step in (["cmake", "-S", project, "-B", binary] + options,
                 ["cmake", "--build", binary]):
        result = subprocess.run(step, capture_output=True, text=True, env=env)
        if result.returncode != 0:
            failures.append(f"{where}: {' '.join(step[:2])} failed\n"
                            f"{(result.stdout + result.stderr)[-3000:]}")
            return
    target = re.findall(r"add_executable\(\s*(\S+)", cmake.text)[0]
    run_checked([os.path.join(binary, target)], project, env, where, failures)


def avs_commands(root):
    with open(os.path.join(root, "avs"), encoding="utf-8") as f:
        text = f.read()
    main = text[text.rfind('case "$cmd" in'):]
    entries = re.findall(r"^  ([a-z][a-z |-]*)\)", main, re.M)
    return {word.strip() for entry in entries for word in entry.split("|")}


def commands_of(text):
    """The shell block's simple commands, as token lists (continuations joined, comments cut)."""
    joined = re.sub(r"\\\n", " ", text)
    commands = []
    for line in joined.split("\n"):
        try:
            tokens = shlex.split(line, comments=True)
        except ValueError:
            tokens = line.split()
        current = []
        for token in tokens:
            if token in ("|", "||", "&&", ";"):
                commands.append(current)
                current = []
            else:
                current.append(token)
        commands.append(current)
    return [c for c in commands if c]


def program_of(token):
    """The name of the project's program that a block's token runs (build/bin/NAME, or
    ../../bin/NAME from a folder of the build), None for any other token."""
    if token.startswith("build/bin/") or token.startswith("../../bin/"):
        return os.path.basename(token)
    return None


def check_shell(block, args, failures):
    where = block.where()
    parsed = subprocess.run(["bash", "-n"], input=block.text, capture_output=True, text=True)
    if parsed.returncode != 0:
        failures.append(f"{where}: does not parse: {parsed.stderr}")
        return
    known = avs_commands(args.root)
    problems = []
    for command in commands_of(block.text):
        # Look past wrappers (environment assignments, xvfb-run and its options, cd).
        for i, token in enumerate(command):
            if token == "./avs" and i + 1 < len(command) and command[i + 1] not in known:
                problems.append(f"./avs has no command '{command[i + 1]}'")
            built = program_of(token)
            if built:
                if built in args.unbuilt:
                    continue
                program = os.path.join(args.build, "bin", built)
                if not os.path.exists(program):
                    problems.append(f"{token} was not built")
                    continue
                with open(program, "rb") as f:
                    binary = f.read()
                for option in command[i + 1:]:
                    name = option.split("=")[0]
                    if name.startswith("--") and name.encode() not in binary:
                        problems.append(f"{token} knows no option {name}")
            for path in re.findall(r"(?:^|[\s\"'=])((?:%s)/[\w./-]+)" % "|".join(REPOSITORY_FOLDERS),
                                   " " + token):
                if not glob.glob(os.path.join(args.root, path.rstrip("/."))):
                    problems.append(f"no {path} in the repository")
    if problems:
        failures.append(f"{where}: " + "; ".join(sorted(set(problems))))
    else:
        print(f"ok (checked, not run): {where}")


def names_unbuilt(block, args):
    """A block that runs a program this build leaves out is checked instead of run."""
    return any(program_of(token) in args.unbuilt
               for command in commands_of(block.text) for token in command)


def run_shell(block, args, scratch, env, failures):
    folder = os.path.join(scratch, f"sh_{block.line}")
    os.makedirs(folder, exist_ok=True)
    os.symlink(args.build, os.path.join(folder, "build"))
    for name in REPOSITORY_FOLDERS + ("avs",):
        os.symlink(os.path.join(args.root, name), os.path.join(folder, name))
    env = {key: value for key, value in env.items() if key != "LD_PRELOAD"}
    run_checked(["bash", "-euo", "pipefail", "-c", block.text], folder, env, block.where(),
                failures)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", required=True)
    parser.add_argument("--build", required=True)
    parser.add_argument("--installed")
    parser.add_argument("--cloud")
    parser.add_argument("--linker-flags", default="")
    parser.add_argument("--pvbatch")
    parser.add_argument("--plugin")
    parser.add_argument("--keep")
    # Programs this build leaves out (the benchmarks, AVS_BUILD_BENCHMARKS=OFF): blocks naming
    # them are checked for everything else.
    parser.add_argument("--unbuilt", nargs="*", default=[])
    args = parser.parse_args()
    args.root, args.build = os.path.abspath(args.root), os.path.abspath(args.build)

    blocks = read_blocks(args.root)
    scratch = args.keep or tempfile.mkdtemp(prefix="avs-docs-")
    if args.keep:
        shutil.rmtree(scratch, ignore_errors=True)
        os.makedirs(scratch)
    if args.cloud and os.path.exists(args.cloud):
        shutil.copy(args.cloud, os.path.join(scratch, "cloud.vdb"))
    env = dict(os.environ)
    env.setdefault("PYTHONDONTWRITEBYTECODE", "1")
    failures, counted = [], 0
    if not args.pvbatch:  # (the plugin's run has the same pages: Docs.CodeBlocks checks them)
        check_links(args.root, failures)
    chains = {}
    cxx = {}
    for block in blocks:
        language = block.language
        if block.mark not in (None, "continue", "pvbatch", "run"):
            failures.append(f"{block.where()}: unknown mark '{block.mark}'")
            continue
        if language == "text":
            continue
        counted += 1
        if args.pvbatch:
            if block.mark == "pvbatch":
                run_pvbatch(block, args, scratch, env, failures)
            continue
        if language == "python":
            if block.mark == "pvbatch":
                print(f"for the plugin's build (pvbatch): {block.where()}")
                continue
            chain = chains.setdefault(block.page, [])
            run_python(block, chain if block.mark == "continue" else [], args, scratch, env,
                       failures)
            if block.mark != "continue":
                chain.clear()
            chain.append(block)
        elif language in ("cpp", "cmake"):
            cxx.setdefault(block.page, []).append(block)
        elif language == "sh":
            if block.mark == "run" and not names_unbuilt(block, args):
                run_shell(block, args, scratch, env, failures)
            else:
                check_shell(block, args, failures)
        else:
            failures.append(f"{block.where()}: a language this test does not know how to run "
                            "(python, cpp with cmake, sh, text)")
    if not args.pvbatch:
        for page, group in cxx.items():
            cmake = [b for b in group if b.language == "cmake"]
            sources = [b for b in group if b.language == "cpp"]
            if len(cmake) != 1 or not sources:
                failures.append(f"{page}: C++ blocks need one cmake block and the sources")
                continue
            build_cxx(page, cmake[0], sources, args, scratch, env, failures)
    print(f"{counted} code blocks in {len({b.page for b in blocks})} pages")
    ran = sum(1 for b in blocks if b.language == "python" and (b.mark == "pvbatch") == bool(args.pvbatch))
    if ran == 0:
        failures.append("no Python block to run: the marks or the pages are wrong")
    if not args.keep and not failures:
        shutil.rmtree(scratch, ignore_errors=True)
    if failures:
        print("FAILED:\n" + "\n\n".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
