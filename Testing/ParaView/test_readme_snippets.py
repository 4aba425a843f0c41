"""Every ```python block of README.md runs as written: blocks that use paraview.simple in
pvpython, the others in the Python of the build tree (PYTHONPATH = its site-packages). Each runs in
a fresh directory where `build` is the build tree, as the README's paths assume. A block fails
when it exits non-zero or prints a VTK error; the failure names the block's line in README.md.

    python3 test_readme_snippets.py --readme README.md --build-dir build \\
        --pythonpath build/lib/python3.11/site-packages --pvpython /usr/bin/pvpython
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile


def python_blocks(readme):
    """(line of the opening fence, code) of every ```python block."""
    blocks, code, start = [], None, 0
    with open(readme, encoding="utf-8") as lines:
        for number, line in enumerate(lines, 1):
            if code is None and re.match(r"^```python\s*$", line):
                code, start = [], number
            elif code is not None and re.match(r"^```\s*$", line):
                blocks.append((start, "".join(code)))
                code = None
            elif code is not None:
                code.append(line)
    return blocks


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--readme", required=True)
    parser.add_argument("--build-dir", required=True)
    parser.add_argument("--pythonpath", required=True)
    parser.add_argument("--pvpython", default="")
    parser.add_argument("--python", default=sys.executable)
    arguments = parser.parse_args()

    blocks = python_blocks(arguments.readme)
    failures = []
    if len(blocks) < 3:
        failures.append("%s: only %d python blocks found" % (arguments.readme, len(blocks)))
    for line, code in blocks:
        uses_paraview = "paraview.simple" in code
        if uses_paraview and not arguments.pvpython:
            failures.append("README.md:%d: the block needs pvpython, which was not found" % line)
            continue
        directory = tempfile.mkdtemp(prefix="readme-%d-" % line)
        os.symlink(os.path.abspath(arguments.build_dir), os.path.join(directory, "build"))
        script = os.path.join(directory, "block.py")
        with open(script, "w", encoding="utf-8") as out:
            out.write(code)
        if uses_paraview:
            command = [arguments.pvpython, "--force-offscreen-rendering", script]
        else:
            command = [arguments.python, script]
        environment = dict(os.environ, PYTHONPATH=os.path.abspath(arguments.pythonpath))
        run = subprocess.run(command, cwd=directory, env=environment, capture_output=True,
                             text=True, timeout=300)
        output = run.stdout + run.stderr
        print("README.md:%d: %s, exit %d" % (line, os.path.basename(command[0]), run.returncode))
        if run.returncode != 0 or re.search(r"\bERROR\b|\bERR\|", output):
            failures.append("README.md:%d: the python block failed (exit %d):\n%s"
                            % (line, run.returncode, output[-2000:]))
    for failure in failures:
        print("FAILED:", failure)
    if failures:
        sys.exit(1)
    print("PASSED: %d README python blocks" % len(blocks))


if __name__ == "__main__":
    main()
