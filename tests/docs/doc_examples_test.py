#!/usr/bin/python3
"""The documentation's command examples give the output they show.

Usage: doc_examples_test.py DOC SOURCE_DIR CAPSUBOT

Every fenced block of the markdown file DOC whose first line is `$ build/capsubot ...` is run
and its output compared with the text shown. In such a block a line starting with `$ ` is a
command (continued over lines ending in a backslash; later commands may be `head`, `cut` and
the like on the files the first wrote); the lines after it, up to the next command, are its
output (standard output and standard error together). The comparison:

* text equal (trailing blanks ignored), numbers equal to 1e-9 relative;
* a line `...` (or `... (a remark)`) stands for any number of lines, none included.

The commands of a block run in a fresh temporary folder where `build/capsubot` is the built
program, `examples` the repository's folder and `results` an empty one: files written with
`-o` land there, never on the tracked results. A block that differs fails the test with the
command and the difference: `-` the documented line, `+` the program's.
"""

import os
import re
import subprocess
import sys
import tempfile

kRelativeTolerance = 1e-9  # the printed digits of two runs agree far beyond this
kCommandSeconds = 300  # per command; the slowest example takes a few seconds
kContext = 2  # matching lines shown around a difference

NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
ELLIPSIS = re.compile(r"^\s*\.\.\.(\s+\(.*\))?\s*$")


def examples(doc_text):
    """Yields (line number, [(command, [expected lines])]) for each checked block."""
    lines = doc_text.split("\n")
    i = 0
    while i < len(lines):
        if not lines[i].startswith("```"):
            i += 1
            continue
        start = i + 1
        end = start
        while end < len(lines) and not lines[end].startswith("```"):
            end += 1
        body = lines[start:end]
        i = end + 1
        if not body or not body[0].startswith("$ build/capsubot "):
            continue
        runs = []
        k = 0
        while k < len(body):
            if body[k].startswith("$ "):
                command = [body[k][2:]]
                while command[-1].endswith("\\") and k + 1 < len(body):
                    k += 1
                    command.append(body[k])
                runs.append(("\n".join(command), []))
            else:
                runs[-1][1].append(body[k])
            k += 1
        yield start + 1, runs


def tokens(line):
    """The line as [text, number, text, ..., text], each number as its text."""
    line = line.rstrip()
    return [part for pair in zip(NUMBER.split(line), NUMBER.findall(line) + [None])
            for part in pair if part is not None]


def difference(expected, actual):
    """None when the lines agree, else what differs."""
    e, a = tokens(expected), tokens(actual)
    if len(e) != len(a) or any(x != y for x, y in zip(e[::2], a[::2])):
        return "different text"
    for x, y in zip(e[1::2], a[1::2]):
        u, v = float(x), float(y)
        if abs(u - v) > kRelativeTolerance * max(abs(u), abs(v)):
            return (f"number {x} shown, {y} printed "
                    f"(relative difference {abs(u - v) / max(abs(u), abs(v)):.2g})")
    return None


def substitution_cost(expected, actual):
    """0 when the lines agree, 1 when only numbers differ, 3 when the text differs: cheaper than
    dropping one line and adding another (2 + 2), so that a changed line shows as one."""
    why = difference(expected, actual)
    if why is None:
        return 0
    return 3 if why == "different text" else 1


kGap = 2  # a documented line with no printed line, or a printed line with no documented one


def align(expected, actual):
    """The cheapest alignment of the documented lines with the printed ones: a list of
    (kind, expected line, printed line), kind '=' (agree), '~' (differ), '-' (documented only),
    '+' (printed only) or '.' (printed lines that a `...` line stands for). Cost 0 = agreement."""
    n, m = len(expected), len(actual)
    dots = [ELLIPSIS.match(e) is not None for e in expected]
    sub = [[substitution_cost(e, a) for a in actual] for e in expected]
    cost = [[0] * (m + 1) for _ in range(n + 1)]
    for j in range(m + 1):
        cost[n][j] = kGap * (m - j)
    for i in range(n - 1, -1, -1):
        for j in range(m, -1, -1):
            if dots[i]:
                cost[i][j] = min(cost[i + 1][j], cost[i][j + 1] if j < m else cost[i + 1][j])
                continue
            best = kGap + cost[i + 1][j]
            if j < m:
                best = min(best, sub[i][j] + cost[i + 1][j + 1], kGap + cost[i][j + 1])
            cost[i][j] = best
    steps, i, j = [], 0, 0
    while i < n or j < m:
        if i == n:
            steps.append(("+", None, actual[j]))
            j += 1
        elif dots[i]:
            if not steps or steps[-1][1] is not expected[i]:
                steps.append(("=", expected[i], None))  # the `...` line, then what it stands for
            if cost[i][j] == cost[i + 1][j]:  # the earliest alignment after a `...`
                i += 1
            else:
                steps.append((".", expected[i], actual[j]))
                j += 1
        elif j < m and cost[i][j] == sub[i][j] + cost[i + 1][j + 1]:
            steps.append(("=" if sub[i][j] == 0 else "~", expected[i], actual[j]))
            i, j = i + 1, j + 1
        elif cost[i][j] == kGap + cost[i + 1][j]:
            steps.append(("-", expected[i], None))
            i += 1
        else:
            steps.append(("+", None, actual[j]))
            j += 1
    return cost[0][0], steps


def report(steps):
    """The differences with a little context, as a diff."""
    wrong = [k for k, s in enumerate(steps) if s[0] in "~-+"]
    shown = set()
    for k in wrong:
        shown.update(range(max(0, k - kContext), min(len(steps), k + kContext + 1)))
    out, last = [], -1
    for k in sorted(shown):
        kind, e, a = steps[k]
        if k != last + 1:
            out.append("  [...]")
        last = k
        if kind == "=":
            out.append("  " + (e if e is not None else a))
        elif kind == ".":
            out.append("  " + a + "   (within a '...')")
        elif kind == "~":
            out += ["- " + e, "+ " + a, "    ^ " + difference(e, a)]
        elif kind == "-":
            out.append("- " + e)
        else:
            out.append("+ " + a)
    return "\n".join(out)


def run_block(runs, source_dir, program):
    """Runs the commands of one block; returns the failures as text."""
    failures = []
    with tempfile.TemporaryDirectory(prefix="capsubot-docs-") as work:
        os.mkdir(os.path.join(work, "build"))
        os.mkdir(os.path.join(work, "results"))
        os.symlink(program, os.path.join(work, "build", "capsubot"))
        os.symlink(os.path.join(source_dir, "examples"), os.path.join(work, "examples"))
        for command, expected in runs:
            try:
                done = subprocess.run(["bash", "-c", command], cwd=work, stdin=subprocess.DEVNULL,
                                      stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                      timeout=kCommandSeconds, check=False)
                actual = done.stdout.decode("utf-8", "replace").split("\n")
            except subprocess.TimeoutExpired:
                failures.append(f"$ {command}\n  timed out after {kCommandSeconds} s")
                continue
            if actual and actual[-1] == "":
                actual.pop()
            cost, steps = align(expected, actual)
            if cost:
                failures.append(f"$ {command}\n{report(steps)}")
    return failures


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: doc_examples_test.py DOC SOURCE_DIR CAPSUBOT")
    doc, source_dir, program = sys.argv[1], os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
    with open(doc, encoding="utf-8") as f:
        blocks = list(examples(f.read()))
    failed = 0
    for line, runs in blocks:
        for failure in run_block(runs, source_dir, program):
            failed += 1
            print(f"FAIL {doc}:{line}: the example's output differs (- shown, + printed):\n{failure}\n")
    print(f"{doc}: {len(blocks)} examples, {failed} differ")
    if not blocks:  # registered because it had examples (tests/CMakeLists.txt): reconfigure
        print(f"FAIL {doc}: no block starts with '$ build/capsubot': nothing checked")
    sys.exit(1 if failed or not blocks else 0)


if __name__ == "__main__":
    main()
