#!/usr/bin/env python3
# Usage (from the repository root): tests/tools/long_functions.py [N] [--tests]
# Lists C++ functions longer than N lines (a brace-matching heuristic: a line that opens a
# block and looks like a signature starts a function; its block's end ends it).
import re, sys, subprocess
N = int(sys.argv[1]) if len(sys.argv) > 1 else 80
files = subprocess.check_output(['git', 'ls-files', '*.cpp', '*.h'], text=True).split()
ctrl = re.compile(r'^\s*(if|for|while|switch|else|do|catch|try|namespace|class|struct|enum|union)\b|=\s*\{?\s*$|\[.*\]\s*\(.*\)\s*(mutable\s*)?\{')
out = []
for f in files:
    if f.startswith('tests/') and '--tests' not in sys.argv: continue
    try: lines = open(f, encoding='utf-8', errors='replace').read().split('\n')
    except Exception: continue
    depth = 0; stack = []; sig = ''
    for i, l in enumerate(lines):
        code = re.sub(r'//.*', '', re.sub(r'"(\\.|[^"\\])*"', '""', l))
        sig = (sig + ' ' + code.strip())[-300:] if code.strip() else sig
        for ch in code:
            if ch == '{':
                is_fn = ')' in sig and not ctrl.search(sig.split(';')[-1]) and not re.search(r'\b(if|for|while|switch)\s*\(', sig.split(';')[-1].split('{')[-1])
                stack.append((i, is_fn, sig.split(';')[-1].split('}')[-1].strip()))
                depth += 1
            elif ch == '}':
                depth -= 1
                if stack:
                    start, is_fn, s = stack.pop()
                    if is_fn and not any(st[1] for st in stack) and i - start + 1 > N:
                        name = re.findall(r'([~\w:]+)\s*\(', s)
                        out.append((i - start + 1, f, start + 1, name[0] if name else s[:60]))
        if code.strip().endswith((';', '{', '}')): sig = ''
for n, f, l, name in sorted(out, reverse=True):
    print(f"{n:4d} {f}:{l} {name}")
