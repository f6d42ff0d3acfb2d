#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""junit-xml.py: the regression's JUnit XML (build/test-results.xml) from scripts/run-tests.sh's
results table, and the per-binary counts of a cmocka XML report.

  junit-xml.py counts CMOCKA_XML          print "PASSED FAILED" of one unit-test binary's report
  junit-xml.py write RESULTS.tsv OUT.xml  write the JUnit XML: one testsuite "unit" with a testcase
                                          per cmocka test, one testsuite "checks" with a testcase per
                                          check script; each failure with its message, log and rerun

RESULTS.tsv rows (tab-separated): kind (unit|check), name, seconds, rc, log, rerun command,
cmocka XML (unit rows). A unit binary whose report is missing or unreadable (a crash) becomes
one failing testcase named after the binary. The layout follows the JUnit schema Jenkins and
GitLab read (testsuites > testsuite > properties, testcase, system-out, system-err), which
tests/checks/junit_xml.sh validates.
"""
import datetime
import os
import socket
import sys
import xml.etree.ElementTree as ET


def cmocka_cases(path):
    """[(name, seconds, failure text or None)] from a cmocka XML report, or None if unreadable."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError):
        return None
    cases = []
    for tc in root.iter("testcase"):
        bad = tc.find("failure")
        if bad is None:
            bad = tc.find("error")
        text = None
        if bad is not None:
            text = (bad.text or bad.get("message") or "failed").strip() or "failed"
        cases.append((tc.get("name", "?"), float(tc.get("time", "0") or 0), text))
    return cases


def tail(path, n=15):
    try:
        with open(path, errors="replace") as f:
            return "".join(f.readlines()[-n:])
    except OSError:
        return "(no log at %s)\n" % path


def first_fail_line(path):
    """The check's own FAIL: line (tests/lib/check.sh), else its last non-empty line."""
    last = ""
    try:
        with open(path, errors="replace") as f:
            for line in f:
                if line.startswith("FAIL:"):
                    return line.strip()
                if line.strip():
                    last = line.strip()
    except OSError:
        pass
    return last or "exited non-zero"


def read_rows(path):
    rows = []
    with open(path) as f:
        for line in f:
            p = line.rstrip("\n").split("\t")
            if len(p) < 6:
                continue
            rows.append({"kind": p[0], "name": p[1], "time": float(p[2]), "rc": int(p[3]),
                         "log": p[4], "rerun": p[5], "report": p[6] if len(p) > 6 else ""})
    return rows


def add_case(suite, classname, name, seconds, failure, log, rerun):
    tc = ET.SubElement(suite, "testcase", name=name, classname=classname, time="%.3f" % seconds)
    if failure is not None:
        msg = failure.splitlines()[0] if failure else "failed"
        f = ET.SubElement(tc, "failure", message=msg[:300], type="failure")
        f.text = "%s\nlog: %s\nrerun: %s\n" % (failure, log, rerun)
    out = ET.SubElement(tc, "system-out")
    out.text = "log: %s\nrerun: %s\n" % (log, rerun)
    return failure is not None


def suite_of(root, name, stamp, host):
    s = ET.SubElement(root, "testsuite", name=name, timestamp=stamp, hostname=host)
    ET.SubElement(s, "properties")
    return s


def write(rows_path, out_path):
    stamp = datetime.datetime.now().replace(microsecond=0).isoformat()
    host = socket.gethostname() or "localhost"
    root = ET.Element("testsuites", name="pree")
    suites = {"unit": suite_of(root, "unit", stamp, host), "check": suite_of(root, "checks", stamp, host)}
    for r in read_rows(rows_path):
        s = suites.get(r["kind"])
        if s is None:
            continue
        if r["kind"] == "unit":
            cases = cmocka_cases(r["report"]) if r["report"] else None
            if not cases:
                why = "no cmocka report (%s): the binary exited with status %d" % (r["report"], r["rc"])
                cases = [(r["name"], r["time"], why if r["rc"] or cases is None else None)]
            for name, sec, text in cases:
                add_case(s, "unit." + r["name"], name, sec,
                         None if text is None else text + "\n" + tail(r["log"]), r["log"], r["rerun"])
        else:
            fail = None if r["rc"] == 0 else first_fail_line(r["log"]) + "\n" + tail(r["log"])
            add_case(s, "checks", r["name"], r["time"], fail, r["log"], r["rerun"])
    total = {"tests": 0, "failures": 0, "time": 0.0}
    for s in suites.values():
        cases = s.findall("testcase")
        n_fail = sum(1 for c in cases if c.find("failure") is not None)
        sec = sum(float(c.get("time")) for c in cases)
        s.set("tests", str(len(cases)))
        s.set("failures", str(n_fail))
        s.set("errors", "0")
        s.set("skipped", "0")
        s.set("time", "%.3f" % sec)
        ET.SubElement(s, "system-out")
        ET.SubElement(s, "system-err")
        total["tests"] += len(cases)
        total["failures"] += n_fail
        total["time"] += sec
    root.set("tests", str(total["tests"]))
    root.set("failures", str(total["failures"]))
    root.set("errors", "0")
    root.set("time", "%.3f" % total["time"])
    ET.indent(root)
    tmp = out_path + ".tmp"
    ET.ElementTree(root).write(tmp, encoding="UTF-8", xml_declaration=True)
    os.replace(tmp, out_path)


def main(argv):
    if len(argv) == 3 and argv[1] == "counts":
        cases = cmocka_cases(argv[2])
        if cases is None:
            print("0 0")
            return 0
        bad = sum(1 for c in cases if c[2] is not None)
        print(len(cases) - bad, bad)
        return 0
    if len(argv) == 4 and argv[1] == "write":
        write(argv[2], argv[3])
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
