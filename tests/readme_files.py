#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: readme_files.py README.md OUT_DIR

Writes each code block of README.md that follows a line `<!-- file: NAME -->` to OUT_DIR/NAME,
as it is written there, so that the tests build what the README shows. Fails when there is none.
"""
import os
import re
import sys

text = open(sys.argv[1]).read()
blocks = re.findall(r"<!-- file: (\S+) -->\n```[a-z]*\n(.*?)```", text, re.S)
if not blocks:
    sys.exit("readme_files.py: no <!-- file: NAME --> block in %s" % sys.argv[1])
os.makedirs(sys.argv[2], exist_ok=True)
for name, body in blocks:
    with open(os.path.join(sys.argv[2], name), "w") as out:
        out.write(body)
    print(name)
