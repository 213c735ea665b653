#!/usr/bin/python3
"""Every Catch2 test case name can become a CTest entry: catch_discover_tests passes the names
through CMake lists, which split at ';' and do not split inside unbalanced '[' ']', so such a
name gives CTest entries whose filters match no test case, and Catch2 exits 0 on them: the test
would never run. Fails naming each such TEST_CASE.
usage: check_test_names.py TESTS_DIR"""
import glob, re, sys

bad = []
for path in sorted(glob.glob(sys.argv[1] + "/*.cpp")):
    text = open(path).read()
    for m in re.finditer(r'TEST_CASE\(\s*"((?:[^"\\]|\\.)*)"', text):
        name = m.group(1)
        depth, balanced = 0, True
        for ch in name:
            depth += (ch == "[") - (ch == "]")
            balanced = balanced and depth >= 0
        if ";" in name or depth != 0 or not balanced:
            bad.append(f"{path}:{text.count(chr(10), 0, m.start()) + 1}: {name}")
for b in bad:
    print("a test case name CTest cannot hold (';' or unbalanced brackets):", b)
print(f"check_test_names.py: {len(bad)} bad names")
sys.exit(1 if bad else 0)
