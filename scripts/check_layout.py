#!/usr/bin/env python3
"""Checks the limits the project keeps on its pages and code (issue 48):

  README.md       at most 200 lines and 16 KB
  BENCHMARK.md    at most 200 lines and 20 KB
  source files    at most 400 lines outside tests/ (C++, CMake, Python, shell)
  src/pipeline/   no function longer than 150 lines
  pages           every relative Markdown link of README.md, BENCHMARK.md and
                  docs/*.md names a file that exists

Prints one line per breach and exits 1 if there is any, 0 otherwise.
  scripts/check_layout.py [CHECKOUT]      (default: the checkout it lives in)
"""
import os
import re
import subprocess
import sys

PAGE_LIMITS = {"README.md": (200, 16 * 1024), "BENCHMARK.md": (200, 20 * 1024)}
MAX_SOURCE_LINES = 400
MAX_FUNCTION_LINES = 150
FUNCTION_DIRS = ("src/pipeline/",)
SOURCE_SUFFIXES = (".cc", ".h", ".cmake", ".py", ".sh")


def tracked_files(root):
    out = subprocess.run(["git", "-C", root, "ls-files"], capture_output=True, text=True)
    if out.returncode != 0:  # not a git checkout: every file under root
        files = []
        for d, _, names in os.walk(root):
            files += [os.path.relpath(os.path.join(d, n), root) for n in names]
        return files
    return out.stdout.split()


def code_only(text):
    """The text with comments, string and character literals blanked
    (newlines kept), so that braces in them are not counted."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif text.startswith('R"', i):  # raw string R"delim( ... )delim"
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def long_functions(path, text):
    """(name, first line, lines) of each function body over the limit: a
    brace block opened outside any other block but namespaces, after a
    closing parenthesis (a function's signature)."""
    code = code_only(text)
    breaches = []
    stack = []  # per open brace: "namespace", "function" or "block"
    head_start = 0  # where the text since the last statement at this depth began
    for i, c in enumerate(code):
        if c == "{":
            head = code[head_start:i]
            if all(k == "namespace" for k in stack):
                if re.search(r"\bnamespace\b", head) or 'extern "C"' in head:
                    stack.append("namespace")
                elif ")" in head and not re.search(r"\b(struct|class|enum|union)\b|=\s*$", head):
                    stack.append(("function", head, i))
                else:
                    stack.append("block")
            else:
                stack.append("block")
            head_start = i + 1
        elif c == "}":
            top = stack.pop() if stack else "block"
            if isinstance(top, tuple):
                _, head, start = top
                first = code.count("\n", 0, start - len(head.lstrip("\n ;")))
                last = code.count("\n", 0, i)
                lines = last - first + 1
                if lines > MAX_FUNCTION_LINES:
                    name = re.findall(r"([\w:~]+)\s*\(", head)
                    breaches.append((name[0] if name else "?", first + 1, lines))
            head_start = i + 1
        elif c == ";":
            head_start = i + 1
    return breaches


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(__file__))
    root = os.path.abspath(root)
    problems = []
    for page, (max_lines, max_bytes) in PAGE_LIMITS.items():
        path = os.path.join(root, page)
        data = open(path, "rb").read()
        lines = data.count(b"\n")
        if lines > max_lines or len(data) > max_bytes:
            problems.append(f"{page}: {lines} lines, {len(data)} bytes "
                            f"(at most {max_lines} lines, {max_bytes} bytes)")
    files = tracked_files(root)
    for f in files:
        if f.startswith("tests/") or not (f.endswith(SOURCE_SUFFIXES) or
                                          os.path.basename(f) == "CMakeLists.txt"):
            continue
        path = os.path.join(root, f)
        if not os.path.isfile(path):
            continue
        text = open(path, encoding="utf-8", errors="replace").read()
        lines = text.count("\n")
        if lines > MAX_SOURCE_LINES:
            problems.append(f"{f}: {lines} lines (at most {MAX_SOURCE_LINES} outside tests/)")
        if f.startswith(FUNCTION_DIRS) and f.endswith(".cc"):
            for name, line, n in long_functions(path, text):
                problems.append(f"{f}:{line}: {name} is {n} lines "
                                f"(at most {MAX_FUNCTION_LINES} in {', '.join(FUNCTION_DIRS)})")
    pages = ["README.md", "BENCHMARK.md"] + sorted(
        os.path.join("docs", p) for p in os.listdir(os.path.join(root, "docs")) if p.endswith(".md"))
    for page in pages:
        text = open(os.path.join(root, page), encoding="utf-8").read()
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+:", target) or target.startswith("#"):
                continue
            file = target.split("#")[0]
            if not os.path.exists(os.path.join(root, os.path.dirname(page), file)):
                problems.append(f"{page}: link to {target}: no such file")
    for p in problems:
        print("check_layout: " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
