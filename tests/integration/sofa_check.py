"""Reads a SOFA scene (scene.scn, XML) with the standard library's xml.etree and prints, as JSON, what the scene
test checks: the MechanicalObjects, the fixed points of each FixedProjectiveConstraint and the MechanicalObject its
mstate link names, and for every TetrahedronFEMForceField the MechanicalObject and the tetrahedra of the topology
its links name. Links ("@dofs", "@../dofs") are resolved as SOFA resolves them: relative to the component's node,
".." for the parent node. Exit 2 when the file is not well-formed XML."""
import json
import sys
import xml.etree.ElementTree as ET


def walk(element, path, out):
    """Collects (node path, element) for every component, the node path as "root/tissue/region1"."""
    for child in element:
        if child.tag == "Node":
            walk(child, path + [child.get("name", "")], out)
        else:
            out.append(("/".join(path), child))


def resolve(node_path, link):
    """The component path a link names, or None when the link is missing or not of the form @[../]*name."""
    if not link or not link.startswith("@"):
        return None
    parts = node_path.split("/")
    target = link[1:].split("/")
    for step in target[:-1]:
        if step == "..":
            if len(parts) <= 1:
                return None
            parts = parts[:-1]
        elif step not in ("", "."):
            parts = parts + [step]
    return "/".join(parts + [target[-1]])


def main(path):
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as error:
        print(json.dumps({"error": str(error)}))
        sys.exit(2)
    components = []
    walk(root, [root.get("name", "")], components)
    by_path = {node + "/" + c.get("name", ""): c for node, c in components}
    plugins = []
    for _, c in components:
        if c.tag == "RequiredPlugin":
            plugins += (c.get("pluginName") or c.get("name") or "").split()
    result = {"plugins": plugins, "gravity": root.get("gravity"), "mechanicalObjects": [], "fixed": [],
              "forceFields": []}
    for node, c in components:
        here = node + "/" + c.get("name", "")
        if c.tag == "MechanicalObject":
            result["mechanicalObjects"].append(here)
        elif c.tag == "FixedProjectiveConstraint":
            result["fixed"].append({"mstate": resolve(node, c.get("mstate")),
                                    "indices": [int(v) for v in c.get("indices", "").split()]})
        elif c.tag == "TetrahedronFEMForceField":
            topology_path = resolve(node, c.get("topology"))
            topology = by_path.get(topology_path)
            tets = [int(v) for v in topology.get("tetrahedra", "").split()] if topology is not None else []
            result["forceFields"].append({
                "node": node, "mstate": resolve(node, c.get("mstate")), "topology": topology_path,
                "topologyType": topology.tag if topology is not None else None,
                "youngModulus": float(c.get("youngModulus", "nan")), "tetrahedra": tets})
    print(json.dumps(result))


if __name__ == "__main__":
    main(sys.argv[1])
