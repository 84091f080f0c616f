#!/usr/bin/python3
"""Checks `citylangsplat query MODEL TEXT --objects` against the city model itself: the objects ranked
before the last one of the expected CityGML type are all of that type (e.g. every bldg:Window first),
by their gml:id in the GML file, and at least --min of them are ranked.

    /usr/bin/python3 tests/viewer/objects_check.py --binary build/citylangsplat --model RUN/language/citylangsplat \\
        --city data/citygml/fzk-haus/fzk_haus_lod3_v2.gml --text window --type Window --out /tmp/objects
Exit status: 0 pass, 1 fail.
"""
import argparse
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

GML_ID = "{http://www.opengis.net/gml}id"


def ids_of_type(city, type_name):
    """gml:ids of the elements named `type_name` in any namespace (bldg:Window, ...)."""
    return {e.get(GML_ID) for e in ET.parse(city).iter() if e.tag.rsplit("}", 1)[-1] == type_name and e.get(GML_ID)}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--binary", required=True)
    p.add_argument("--model", required=True, help="language model directory")
    p.add_argument("--city", required=True, help="the CityGML file the model's label maps were made from")
    p.add_argument("--text", required=True)
    p.add_argument("--type", required=True, help="CityGML element name the text should answer with (Window)")
    p.add_argument("--min", type=int, default=5, help="objects of that type that must be ranked")
    p.add_argument("--out", required=True)
    args = p.parse_args()

    expected = ids_of_type(args.city, args.type)
    subprocess.run([args.binary, "query", args.model, args.text, "--objects", "--no-maps", "--out", args.out],
                   check=True)
    slug = "".join(c if c.isalnum() else "_" for c in args.text.lower()).strip("_")
    rows = json.load(open(os.path.join(args.out, f"objects_{slug}.json")))["objects"]
    hits = [i for i, r in enumerate(rows) if r["id"] in expected]
    print(f"{len(expected)} {args.type} objects in {args.city}; {len(hits)} of {len(rows)} ranked objects are of them, "
          f"at ranks {[i + 1 for i in hits]}")
    failures = []
    if len(hits) < args.min:
        failures.append(f"only {len(hits)} {args.type} objects ranked (< {args.min})")
    if hits and hits[-1] != len(hits) - 1:
        others = [f"{r['class']} {r['id']} (rank {i + 1})" for i, r in enumerate(rows[:hits[-1]]) if r["id"] not in expected]
        failures.append(f"ranked before the last {args.type}: {', '.join(others)}")
    for f in failures:
        print(f"FAIL: {f}")
    if not failures:
        print("PASS")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
