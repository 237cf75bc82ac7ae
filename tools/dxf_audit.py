#!/usr/bin/env python3
"""Independent check of DXF files written by tmm-sheets' DXF backend (tests/dxf.rs).

    python3 tools/dxf_audit.py FILE.dxf [FILE.dxf ...]

Needs ezdxf 1.4.5:  python3 -m pip install --quiet ezdxf==1.4.5

Each FILE is loaded with ezdxf.readfile and checked with ezdxf's auditor; every error and
every fix the auditor reports is printed on stderr. For each FILE, in order, one line of
JSON is printed on stdout:

    {"file": ..., "version": "AC1015", "insunits": 4, "errors": 0, "fixes": 0,
     "counts": {"LINE": 12, ...}, "texts": [...], "layers": {...}}

`counts`: the model space's entities by dxftype (a POLYLINE once, its VERTEX and SEQEND
not). `texts`: each TEXT's text in file order, its \\U+XXXX escapes decoded by ezdxf's
decode_dxf_unicode. `layers`: each layer's linetype and lineweight (1/100 mm; -3 when the
version has none).

Exit status: 0 when every file loads and its audit reports no error and no fix; 1
otherwise; 2 when ezdxf cannot be imported (the Rust test then reports "skipped").
"""

import json
import sys

try:
    import ezdxf
except ImportError:
    print("ezdxf not installed", file=sys.stderr)
    sys.exit(2)


def check(path: str) -> bool:
    try:
        doc = ezdxf.readfile(path)
    except (IOError, ezdxf.DXFError) as e:
        print(f"{path}: not loadable: {e}", file=sys.stderr)
        print(json.dumps({"file": path, "loaded": False}))
        return False
    auditor = doc.audit()
    for e in auditor.errors:
        print(f"{path}: ERROR {e.code}: {e.message}", file=sys.stderr)
    for f in auditor.fixes:
        print(f"{path}: FIX {f.code}: {f.message}", file=sys.stderr)
    counts = {}
    texts = []
    for e in doc.modelspace():
        t = e.dxftype()
        counts[t] = counts.get(t, 0) + 1
        if t == "TEXT":
            texts.append(ezdxf.decode_dxf_unicode(e.dxf.text))
    layers = {
        layer.dxf.name: {
            "linetype": layer.dxf.linetype,
            "lineweight": layer.dxf.get("lineweight", -3),
        }
        for layer in doc.layers
    }
    out = {
        "file": path,
        "loaded": True,
        "version": doc.dxfversion,
        "insunits": doc.header.get("$INSUNITS", 0),
        "errors": len(auditor.errors),
        "fixes": len(auditor.fixes),
        "counts": dict(sorted(counts.items())),
        "texts": texts,
        "layers": layers,
    }
    print(json.dumps(out, ensure_ascii=False))
    return not auditor.errors and not auditor.fixes


def main() -> int:
    files = sys.argv[1:]
    if not files:
        print(__doc__, file=sys.stderr)
        return 2
    ok = [check(f) for f in files]
    return 0 if all(ok) else 1


if __name__ == "__main__":
    sys.exit(main())
