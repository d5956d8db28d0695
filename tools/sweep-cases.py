#!/usr/bin/env python3
"""Writes the 20-case sweep: ages 20-75, parity 0-4, every supported FIGO type (0-7, 2-5) and polyps.

Used to check that a change keeps the scene bytes (docs/build-and-test.md, "Byte-identical output") and by the
sweeps of the scene tests. The cases are a deterministic function of this file: run it again, get the same files.

    python3 tools/sweep-cases.py OUT_DIR     # writes OUT_DIR/sweep-00.json .. sweep-19.json
"""
import copy
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT = os.path.join(HERE, "..", "resources", "cases", "default.json")

FIGO = ["0", "1", "2", "3", "4", "5", "6", "7", "2-5"]
LOCATIONS = ["posterior", "anterior", "fundal", "left-lateral", "right-lateral"]
MYOMA_MODELS = ["skeleton", "particles", "ca"]
POLYP_MODELS = ["skeleton", "particles"]
POSTMENOPAUSAL_SUBMUCOSAL_MAX_MM = 20.0  # Lasmar size score 0 (docs/references.md [Lasmar2005])


def figo_value(text):
    return int(text) if "-" not in text else text


def sweep_case(i, base):
    case = copy.deepcopy(base)
    age = 20 + round(i * 55 / 19)  # 20 .. 75
    parity = i % 5
    case["title"] = f"Sweep {i:02d}: {age} years, parity {parity}"
    case["seed"] = 1000 + i
    patient = case["patient"]
    patient["ageYears"] = float(age)
    patient["parity"] = parity
    patient["gravidity"] = parity + (i % 2)
    patient["heightCm"] = 155.0 + (i * 7) % 30
    patient["weightKg"] = 55.0 + (i * 11) % 40
    patient["menopausal"] = age >= 55
    # The cycle phase sets the endometrium's thickness; a postmenopausal patient has none.
    patient["cyclePhase"] = None if age >= 55 else ["menstrual", "proliferative", "secretory"][i % 3]
    pathologies = []
    # Every case has a myoma; the FIGO types cycle so that each appears at least twice.
    figo = FIGO[i % len(FIGO)]
    size = 15.0 + (i * 3) % 12
    if patient["menopausal"] and figo in ("0", "1"):
        # A FIGO 0 or 1 myoma stands mostly in the cavity, and the cavity after menopause is small (the model's
        # 72- and 75-year-olds: 22-23 mm long, 17 mm between the ostia, about 5 mm deep): a 24 mm one is longer than
        # the whole cavity and covers the fundus. Leiomyomas regress after menopause (Stewart, N Engl J Med 2015;
        # 372:1646-55), so these are drawn from Lasmar's smallest size class, <= 20 mm
        # (docs/references.md [Stewart2015], [Lasmar2005]).
        size = min(size, POSTMENOPAUSAL_SUBMUCOSAL_MAX_MM)
    pathologies.append({
        "id": "myoma-1",
        "kind": "myoma",
        "growthModel": MYOMA_MODELS[i % len(MYOMA_MODELS)],
        "sizeMm": size,
        "figo": figo_value(figo),
        "placement": {"location": LOCATIONS[i % len(LOCATIONS)]},
    })
    # Every other case also has a polyp, sessile or pedunculated, fundal or in a cornu.
    if i % 2 == 0:
        pedunculated = (i // 2) % 2 == 1
        polyp = {
            "id": "polyp-1",
            "kind": "polyp",
            "growthModel": POLYP_MODELS[(i // 2) % len(POLYP_MODELS)],
            "sizeMm": 8.0 + (i % 4),
            "attachment": "pedunculated" if pedunculated else "sessile",
            "stalkLengthMm": 6.0 if pedunculated else None,
            "placement": {"location": "fundal" if i % 4 == 0 else "cornual-right"},
        }
        pathologies.append(polyp)
    case["pathologies"] = pathologies
    return case


def main():
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        sys.stderr.write(__doc__)
        return 0 if len(sys.argv) == 2 else 2
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    with open(DEFAULT, encoding="utf-8") as f:
        base = json.load(f)
    for i in range(20):
        path = os.path.join(out, f"sweep-{i:02d}.json")
        with open(path + ".tmp", "w", encoding="utf-8") as f:
            json.dump(sweep_case(i, base), f, indent=4)
            f.write("\n")
        os.replace(path + ".tmp", path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
