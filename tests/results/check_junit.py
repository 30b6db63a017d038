#!/usr/bin/env python3
"""Structural check of hilrig's junit.xml against Jenkins' JUnit schema (xunit-plugin
junit-10.xsd): element nesting, required attributes, allowed attributes, and counts that add
up. Independent of the C++ writer: it only reads the XML."""
import re
import sys
import xml.etree.ElementTree as ET

ALLOWED = {
    "testsuites": {"name", "time", "tests", "failures", "errors"},
    "testsuite": {"name", "tests", "failures", "errors", "group", "time", "skipped", "timestamp",
                  "hostname", "id", "package", "file", "log", "url"},
    "testcase": {"name", "time", "classname", "group"},
    "failure": {"type", "message"},
    "error": {"type", "message"},
    "skipped": {"type", "message"},
    "properties": set(),
    "property": {"name", "value"},
    "system-out": set(),
    "system-err": set(),
}
REQUIRED = {
    "testsuite": {"name", "tests", "failures", "errors"},
    "testcase": {"name"},
    "property": {"name", "value"},
}
CHILDREN = {
    "testsuites": {"testsuite"},
    "testsuite": {"testsuite", "properties", "testcase", "system-out", "system-err"},
    "testcase": {"skipped", "error", "failure", "system-out", "system-err"},
    "properties": {"property"},
}
TIME = re.compile(r"^(([0-9]{0,3},)*[0-9]{3}|[0-9]{0,3})*(\.[0-9]*)?$")

problems = []


def walk(el, path):
    here = f"{path}/{el.tag}"
    extra = set(el.attrib) - ALLOWED.get(el.tag, set())
    if el.tag not in ALLOWED:
        problems.append(f"{here}: unknown element")
    if extra:
        problems.append(f"{here}: attributes not in the schema: {sorted(extra)}")
    missing = REQUIRED.get(el.tag, set()) - set(el.attrib)
    if missing:
        problems.append(f"{here}: missing required attributes {sorted(missing)}")
    if "time" in el.attrib and not TIME.match(el.attrib["time"]):
        problems.append(f"{here}: time {el.attrib['time']!r} is not a SUREFIRE_TIME")
    for child in el:
        if child.tag not in CHILDREN.get(el.tag, set()):
            problems.append(f"{here}: {child.tag} not allowed here")
        walk(child, here)


def main():
    root = ET.parse(sys.argv[1]).getroot()
    if root.tag != "testsuites":
        problems.append(f"root is {root.tag}, not testsuites")
    walk(root, "")
    totals = {"tests": 0, "failures": 0, "errors": 0}
    for suite in root.iter("testsuite"):
        cases = suite.findall("testcase")
        counted = {
            "tests": len(cases),
            "failures": sum(1 for c in cases if c.find("failure") is not None),
            "errors": sum(1 for c in cases if c.find("error") is not None),
            "skipped": sum(1 for c in cases if c.find("skipped") is not None),
        }
        for key, n in counted.items():
            if int(suite.attrib.get(key, "0")) != n:
                problems.append(f"suite {suite.attrib['name']}: {key}={suite.attrib.get(key)} but {n} found")
        for key in totals:
            totals[key] += counted[key]
    for key, n in totals.items():
        if int(root.attrib.get(key, "-1")) != n:
            problems.append(f"testsuites: {key}={root.attrib.get(key)} but {n} found")
    # The sample holds one of each verdict: make sure each kind really appears.
    for tag in ("failure", "error", "skipped", "property", "system-out"):
        if root.find(f".//{tag}") is None:
            problems.append(f"the sample should contain a <{tag}>")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
