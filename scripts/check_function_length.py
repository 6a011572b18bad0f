#!/usr/bin/env python3
"""Lists the C++ functions longer than 80 lines in the given files or folders.

A function is a brace block at namespace or class level whose head (the text
since the previous ';', '{' or '}' at that level) holds a parameter list and is
not a class, struct, union, enum or namespace; its length runs from the first
line of that head to its closing brace. Comments, strings and preprocessor
lines are skipped. Usage: check_function_length.py [--max N] PATH...; exits
with 1 if a function is longer, 0 otherwise. With --self-test, checks the
counting on a small sample instead.
"""
import pathlib
import re
import sys

NOT_FUNCTION = re.compile(r"\b(class|struct|union|enum|namespace)\b")
CPP = (".h", ".hpp", ".cpp", ".cc")


def strip(text):
    """`text` with comments, strings and character literals blanked (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
            i = j
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            k = text.find("(", i)
            delim = ")" + text[i + 2:k] + '"'
            j = text.find(delim, k)
            j = n if j < 0 else j + len(delim)
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (min(j, n - 1) + 1 - i))
            i = j + 1
        else:
            out.append(c)
            i += 1
    lines = "".join(out).split("\n")
    return "\n".join("" if l.lstrip().startswith("#") else l for l in lines)


def functions(text):
    """(name line, first line, last line) of each function of `text`."""
    code = strip(text)
    found, depth, head_start, head = [], 0, 0, []
    stack = []  # per open brace: (is_function, start line, head text) or None
    line = 1
    in_function = 0
    for ch in code:
        if ch == "\n":
            line += 1
        if in_function == 0 and ch not in "{};" and not head and not ch.isspace():
            head_start = line
        if ch == "{":
            h = "".join(head)
            is_function = in_function == 0 and "(" in h and not NOT_FUNCTION.search(h.split("(")[0])
            stack.append((is_function, head_start, h))
            if is_function or in_function:
                in_function += 1
            head = []
        elif ch == "}":
            if stack:
                is_function, start, h = stack.pop()
                if in_function:
                    in_function -= 1
                    if in_function == 0 and is_function:
                        name = h.split("(")[0].split()[-1] if h.split("(")[0].split() else "?"
                        found.append((name, start, line))
            head = []
        elif ch == ";":
            if in_function == 0:
                head = []
        elif in_function == 0:
            if ch.isspace() and not head:
                continue
            if not head:
                head_start = line
            head.append(ch)
    return found


def self_test():
    sample = "namespace a {\nstruct S {\n  int f(int x)\n  {\n    if(x) { return 1; }\n    return 0;\n  }\n};\n" \
             "// }\nint g()\n{\n  const char* s = \"}\";\n  auto l = [](int y) { return y; };\n  return l(1);\n}\n}\n"
    got = [(n, b, e) for n, b, e in functions(sample)]
    want = [("f", 3, 7), ("g", 10, 15)]
    if got == want:
        print("self-test: the sample's functions were measured")
        return 0
    print("self-test failed:", got, "instead of", want)
    return 1


def main(args):
    limit = 80
    if args[:1] == ["--self-test"]:
        return self_test()
    if args[:1] == ["--max"]:
        limit, args = int(args[1]), args[2:]
    files = []
    for a in args:
        p = pathlib.Path(a)
        files += sorted(q for q in p.rglob("*") if q.suffix in CPP) if p.is_dir() else [p]
    long_ones = 0
    for f in files:
        for name, first, last in functions(f.read_text()):
            if last - first + 1 > limit:
                print(f"{f}:{first}: {name}() is {last - first + 1} lines (at most {limit})")
                long_ones += 1
    return 1 if long_ones else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
