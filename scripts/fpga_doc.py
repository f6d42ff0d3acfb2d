#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""fpga_doc.py: put a generated table into a document between its markers.

Usage: fpga_doc.py <doc.md> <name> <table.md>
Replaces everything between the lines "<!-- <name>:begin -->" and "<!-- <name>:end -->" of
doc.md with the contents of table.md (make fpga-timing: the tables of docs/fpga.md are written
by the commands that measured them, never typed). Fails if the markers are missing.
"""
import sys


def main():
    if len(sys.argv) != 4:
        raise SystemExit("usage: fpga_doc.py <doc.md> <name> <table.md>")
    doc, name, table = sys.argv[1:]
    text = open(doc).read()
    begin, end = "<!-- %s:begin -->\n" % name, "<!-- %s:end -->" % name
    if begin not in text or end not in text:
        raise SystemExit("fpga_doc: markers of %s missing in %s" % (name, doc))
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    body = open(table).read()
    if not body.endswith("\n"):
        body += "\n"
    open(doc, "w").write(head + begin + body + end + tail)


if __name__ == "__main__":
    main()
