#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""junit_validate.py FILE.xml: check a JUnit XML report against the structure of the JUnit
schema that CI servers read (Jenkins' junit-4.xsd, which GitLab and GitHub reporters accept):
a <testsuites> root of <testsuite> elements, each with name, tests, failures, errors, time,
timestamp (ISO 8601) and hostname, children in the order properties, testcase*, system-out,
system-err; each <testcase> with name, classname and a decimal time, at most one failure or
error with a message; counts that agree with the testcases. Prints one line per problem
and exits 1 on any, else prints a summary and exits 0."""
import datetime
import re
import sys
import xml.etree.ElementTree as ET

DEC = re.compile(r"^[0-9]+(\.[0-9]+)?$")
INT = re.compile(r"^[0-9]+$")


def check_suite(s, where, bad):
    for a in ("name", "tests", "failures", "errors", "time", "timestamp", "hostname"):
        if not s.get(a):
            bad.append("%s: missing attribute %s" % (where, a))
    for a in ("tests", "failures", "errors", "skipped"):
        if s.get(a) is not None and not INT.match(s.get(a)):
            bad.append("%s: %s=%r is not a count" % (where, a, s.get(a)))
    if s.get("time") and not DEC.match(s.get("time")):
        bad.append("%s: time=%r is not a decimal" % (where, s.get("time")))
    try:
        datetime.datetime.fromisoformat(s.get("timestamp", ""))
    except ValueError:
        bad.append("%s: timestamp %r is not ISO 8601" % (where, s.get("timestamp")))
    order = [c.tag for c in s]
    want = re.compile(r"^(properties )?(testcase )*(system-out )(system-err )$")
    if not want.match("".join(t + " " for t in order)):
        bad.append("%s: children %s not in the order properties, testcase*, system-out, system-err"
                   % (where, order))
    cases = s.findall("testcase")
    fails = 0
    for i, c in enumerate(cases):
        w = "%s testcase %d (%s)" % (where, i, c.get("name"))
        for a in ("name", "classname", "time"):
            if not c.get(a):
                bad.append("%s: missing attribute %s" % (w, a))
        if c.get("time") and not DEC.match(c.get("time")):
            bad.append("%s: time=%r is not a decimal" % (w, c.get("time")))
        res = [x for x in c if x.tag in ("failure", "error", "skipped")]
        if len(res) > 1:
            bad.append("%s: more than one failure/error/skipped" % w)
        for x in res:
            if x.tag in ("failure", "error") and x.get("message") is None:
                bad.append("%s: %s without a message" % (w, x.tag))
        for x in c:
            if x.tag not in ("failure", "error", "skipped", "system-out", "system-err"):
                bad.append("%s: unexpected element <%s>" % (w, x.tag))
        fails += sum(1 for x in res if x.tag == "failure")
    if s.get("tests") and INT.match(s.get("tests")) and int(s.get("tests")) != len(cases):
        bad.append("%s: tests=%s but %d testcases" % (where, s.get("tests"), len(cases)))
    if s.get("failures") and INT.match(s.get("failures")) and int(s.get("failures")) != fails:
        bad.append("%s: failures=%s but %d failing testcases" % (where, s.get("failures"), fails))
    return len(cases), fails


def main(path):
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as e:
        print("%s: not XML: %s" % (path, e))
        return 1
    bad = []
    if root.tag != "testsuites":
        bad.append("%s: root is <%s>, not <testsuites>" % (path, root.tag))
    n = f = 0
    for i, s in enumerate(root):
        if s.tag != "testsuite":
            bad.append("%s: child %d is <%s>, not <testsuite>" % (path, i, s.tag))
            continue
        a, b = check_suite(s, "%s: testsuite %s" % (path, s.get("name")), bad)
        n += a
        f += b
    for line in bad:
        print(line)
    if bad:
        return 1
    print("%s: valid JUnit XML, %d testsuites, %d testcases, %d failures" % (path, len(root), n, f))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]) if len(sys.argv) == 2 else 2)
