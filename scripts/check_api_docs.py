#!/usr/bin/env python3
"""Checks the API reference's XML (Doxygen) for what Doxygen cannot warn about:
every public function says what it throws.

A public function either is declared noexcept, or its documentation has at
least one \\throws entry (a function that throws nothing of its own but
allocates says `\\throws std::bad_alloc`). Deleted and defaulted functions
are exempt. Usage: check_api_docs.py BUILD/docs/api/xml
"""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path


def exempt(argsstring: str) -> bool:
    compact = argsstring.replace(" ", "")
    return "noexcept" in compact or compact.endswith("=delete") or compact.endswith("=default")


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    xml_dir = Path(sys.argv[1])
    files = sorted(xml_dir.glob("*.xml"))
    if not files:
        print(f"check_api_docs: no XML in {xml_dir} (run the subdiv_docs target first)", file=sys.stderr)
        return 2
    seen, missing = set(), []
    for path in files:
        if path.name in ("index.xml", "Doxyfile.xml"):
            continue
        for member in ET.parse(path).getroot().iter("memberdef"):
            if member.get("kind") != "function" or member.get("prot") != "public":
                continue
            ident = member.get("id")
            if ident in seen:
                continue
            seen.add(ident)
            if exempt(member.findtext("argsstring") or ""):
                continue
            detail = member.find("detaileddescription")
            lists = detail.iter("parameterlist") if detail is not None else []
            if not any(p.get("kind") == "exception" for p in lists):
                location = member.find("location")
                where = f"{location.get('file')}:{location.get('line')}" if location is not None else "?"
                name = member.findtext("qualifiedname") or member.findtext("name")
                missing.append(f"{where}: {name}{member.findtext('argsstring')} has no \\throws (or noexcept)")
    for line in sorted(missing):
        print(line, file=sys.stderr)
    print(f"check_api_docs: {len(seen)} public functions, {len(missing)} without \\throws or noexcept",
          file=sys.stderr if missing else sys.stdout)
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
