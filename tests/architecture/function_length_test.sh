#!/usr/bin/env bash
# No function is longer than 80 lines. A function's length counts every line from the first
# line of its signature (a `template <...>` line or a decorator included; the comments above it
# not) to its closing brace (in Python its last line), both included: blank and comment lines
# inside count too. Checked are the C++ files (*.cpp, *.hpp) and the Python files (*.py) of
# src/, apps/ and python/.
# In C++ a function body is a brace block opened where declarations stand (the top level of a
# file, a namespace or a class) after a head that holds a parenthesis and is not a class, an
# enum, a namespace or an initialiser (`x = {...}`), or after a lambda that initialises a
# variable there. A lambda or a local class inside a function counts towards that function.
# Comments, string and character literals and preprocessor lines are blanked out before the
# braces are matched. In Python every `def` counts, a method or a nested function too.
# The scanner first checks itself on samples (a function of 81 lines is found, one of 80 is
# not, braces in literals and comments are ignored, ...); then every offender is printed as
# file:line: name: length, and the test fails if there is one.
# Usage: function_length_test.sh SOURCE_DIR
set -euo pipefail
cd "$1"

exec python3 - <<'PYTHON'
import ast
import pathlib
import re
import sys

MAX_LINES = 80
FOLDERS = ("src", "apps", "python")
# file: {function: reason} allowed to be longer: none.
ALLOWED = {}


def blank(text):
    """The text with every character but the newlines replaced by a space."""
    return re.sub(r"[^\n]", " ", text)


def blank_code(text):
    """The C++ text with comments, literals and preprocessor lines blanked out (newlines kept,
    so that line numbers are unchanged)."""
    out = []
    i, n = 0, len(text)
    at_line_start = True  # only blanks since the last newline
    while i < n:
        c = text[i]
        if at_line_start and c == "#":  # a preprocessor line, with its continuations
            j = i
            while True:
                j = text.find("\n", j)
                if j < 0 or text[j - 1] != "\\":
                    break
                j += 1
            j = n if j < 0 else j
        elif text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif text.startswith('R"', i) and not (i > 0 and (text[i - 1].isalnum() or
                                                          text[i - 1] == "_")):
            delimiter = re.match(r'R"([^(\s]*)\(', text[i:]).group(1)
            j = text.find(")" + delimiter + '"', i) + len(delimiter) + 2
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            j += 1
        else:
            out.append(c)
            if c == "\n":
                at_line_start = True
            elif c not in " \t":
                at_line_start = False
            i += 1
            continue
        out.append(blank(text[i:j]))
        at_line_start = False
        i = j
    return "".join(out)


def without_template(head):
    """The head without its `template <...>` parameter lists (`class` is a keyword there)."""
    while True:
        m = re.search(r"\btemplate\s*<", head)
        if not m:
            return head
        depth, k = 0, m.end() - 1
        for k in range(m.end() - 1, len(head)):
            depth += {"<": 1, ">": -1}.get(head[k], 0)
            if depth == 0:
                break
        head = head[:m.start()] + head[k + 1:]


def head_kind(head):
    """What a brace opened where declarations stand, after `head` (the code since the previous
    ; { or } there), starts: a "function" body, a "scope" of declarations (namespace, class) or
    a "block" of something else (enumerators, an initialiser)."""
    head = without_template(head)
    head = re.sub(r"\boperator\s*(\(\)|\[\]|[^\s(]+)", "operator_", head)
    if not head.strip():
        return "block"
    if re.search(r"\bnamespace\b", head) or re.match(r"\s*extern\b", head):
        return "scope"
    depth, assigns = 0, False
    for k, ch in enumerate(head):
        if ch in "([<":
            depth += 1
        elif ch in ")]>" and depth > 0:
            depth -= 1
        elif ch == "=" and depth == 0 and head[k + 1:k + 2] != "=" and \
                head[k - 1:k] not in ("=", "!", "<", ">"):
            assigns = True
    if assigns:  # an initialiser: a lambda's body counts as a function
        return "function" if re.search(r"\]\s*(\(|\{|mutable)", head) else "block"
    declares = head.split("(")[0]
    if re.search(r"\benum\b", declares):
        return "block"
    if re.search(r"\b(class|struct|union)\b", declares):
        return "scope"
    return "function" if "(" in head else "block"


def function_name(head):
    if re.search(r"=\s*\[", head):  # a lambda: the variable's name
        m = re.search(r"([\w:]+)\s*=\s*\[", head)
    else:
        m = re.search(r"\b(operator\s*(?:\(\)|\[\]|[^\s(]+))", head) or \
            re.search(r"([~\w:]+)\s*\(", head)
    return re.sub(r"\s", "", m.group(1)) if m else head.strip().split("\n")[0]


def find_close(code, i):
    """The index of the brace that closes the one at i."""
    depth = 0
    for j in range(i, len(code)):
        depth += {"{": 1, "}": -1}.get(code[j], 0)
        if depth == 0:
            return j
    return len(code) - 1


def cpp_functions(text):
    """(first line, name, length) of every function of a C++ text."""
    code = blank_code(text)
    line_of = []
    for number, line in enumerate(code.split("\n"), 1):
        line_of.extend([number] * (len(line) + 1))
    found = []
    stack = []  # one entry per open brace: (kind, where its head starts)
    head_start = 0
    i = 0
    while i < len(code):
        c = code[i]
        declarations = all(kind == "scope" for kind, _ in stack)
        if c == "{":
            head = code[head_start:i]
            kind = head_kind(head) if declarations else "inner"
            # A constructor's member initialisers `) : a_{x}, b_{y} {`: the body's brace
            # follows a ) or a }, a member's brace follows its name.
            if kind == "function" and re.search(r"\)\s*:(?!:)", head) and \
                    re.search(r"[\w>]\s*$", head):
                i = find_close(code, i) + 1
                continue
            stack.append((kind, head_start))
            head_start = i + 1
        elif c == "}":
            kind, start = stack.pop() if stack else ("block", 0)
            if kind == "function":
                head = code[start:]
                first = start + len(head) - len(head.lstrip())
                found.append((line_of[first], function_name(code[first:code.index("{", first)]),
                              line_of[i] - line_of[first] + 1))
            head_start = i + 1
        elif c == ";" and declarations:
            head_start = i + 1
        i += 1
    return found


def python_functions(text, name="<text>"):
    """(first line, name, length) of every function of a Python text."""
    found = []
    for node in ast.walk(ast.parse(text, name)):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            first = min([node.lineno] + [d.lineno for d in node.decorator_list])
            found.append((first, node.name, node.end_lineno - first + 1))
    return found


def self_test():
    """The scanner on samples whose functions are known; the failures it finds."""
    body = lambda lines: "".join(f"  x += {k};\n" for k in range(lines))
    # A function of 2 + k lines (signature, k body lines, closing brace).
    samples = [
        (f"int Long(int x) {{\n{body(79)}}}\n", [(1, "Long", 81)]),
        (f"int Short(int x) {{\n{body(78)}}}\n", [(1, "Short", 80)]),
        (f"// c {{\ntemplate <class T>\nT Twice(T x,\n        T y) {{\n{body(2)}}}\n",
         [(2, "Twice", 6)]),
        (f"namespace a {{\nstruct S : B {{\n  S(int x) : x_{{x}}, y_{{x}} {{\n{body(3)}  }}\n"
         f"  int x_, y_;\n}};\n}}  // namespace a\n", [(3, "S", 5)]),
        (f'void Text() {{\n  f("}}", \'{{\', R"({{)");  // }}\n  /* {{ */\n{body(1)}}}\n'
         f"void After() {{}}\n", [(1, "Text", 5), (6, "After", 1)]),
        (f"const auto kLambda = [](int x) {{\n{body(2)}}};\n", [(1, "kLambda", 4)]),
        ("enum class E { kA, kB };\nconst int kTable[] = {\n  1,\n  2};\n"
         "bool operator==(A a, A b) {\n  return true;\n}\n", [(5, "operator==", 3)]),
        ("#define M(x) { x }\nextern \"C\" {\nvoid C() {\n}\n}\n", [(3, "C", 2)]),
    ]
    failures = []
    for text, expected in samples:
        if cpp_functions(text) != expected:
            failures.append(f"{text.splitlines()[0]!r}...: {cpp_functions(text)} instead of "
                            f"{expected}")
    python = "@decorated\ndef f(x):\n" + "    x += 1\n" * 79 + "\nclass C:\n  def g(self):\n" \
        "    pass\n"
    expected = [(1, "f", 81), (84, "g", 2)]
    if sorted(python_functions(python)) != expected:
        failures.append(f"Python: {sorted(python_functions(python))} instead of {expected}")
    return failures


failures = self_test()
for failure in failures:
    print(f"FAIL: the scanner on a sample: {failure}")
checked = failed = 0
used = set()
for folder in FOLDERS:
    for path in sorted(pathlib.Path(folder).rglob("*")):
        if path.suffix not in (".cpp", ".hpp", ".py"):
            continue
        checked += 1
        text = path.read_text()
        functions = python_functions(text, str(path)) if path.suffix == ".py" else \
            cpp_functions(text)
        for line, name, length in functions:
            if length <= MAX_LINES:
                continue
            reason = ALLOWED.get(str(path), {}).get(name)
            if reason is not None:
                print(f"allowed: {path}:{line}: {name}: {length} lines ({reason})")
                used.add((str(path), name))
                continue
            print(f"FAIL: {path}:{line}: {name}: {length} lines (at most {MAX_LINES})")
            failed += 1
for path, names in ALLOWED.items():
    for name in names:
        if (path, name) not in used:
            print(f"note: {path}: {name} is within {MAX_LINES} lines: its exception can go")
print(f"{checked} files checked, {failed} functions over {MAX_LINES} lines")
sys.exit(0 if not failures and checked > 100 and failed == 0 else 1)
PYTHON
