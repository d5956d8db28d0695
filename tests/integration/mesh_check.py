"""Reads a tetrahedral file with meshio (or, with --paraview, ParaView's XML reader; with --vtk, VTK's Python reader) and prints its tetrahedron
count and the region id of every tetrahedron as JSON. Exit 3 when the library is missing (the test skips)."""
import json
import sys


def with_meshio(path):
    try:
        import meshio
    except ImportError:
        sys.exit(3)
    mesh = meshio.read(path)
    regions = []
    key = "region" if "region" in mesh.cell_data else "gmsh:physical"
    for block, data in zip(mesh.cells, mesh.cell_data[key]):
        if block.type == "tetra":
            regions += [int(v) for v in data]
    tets = sum(len(block.data) for block in mesh.cells if block.type == "tetra")
    return {"tets": tets, "regions": regions, "arrays": sorted(mesh.cell_data.keys())}


def with_paraview(path):
    try:
        from paraview import simple, servermanager
    except ImportError:
        sys.exit(3)
    reader = simple.XMLUnstructuredGridReader(FileName=[path])
    reader.UpdatePipeline()
    grid = servermanager.Fetch(reader)
    array = grid.GetCellData().GetArray("region")
    regions = [int(array.GetValue(i)) for i in range(array.GetNumberOfTuples())] if array else []
    tets = sum(1 for i in range(grid.GetNumberOfCells()) if grid.GetCellType(i) == 10)
    arrays = sorted(grid.GetCellData().GetArrayName(i) for i in range(grid.GetCellData().GetNumberOfArrays()))
    return {"tets": tets, "regions": regions, "arrays": arrays}


def with_vtk(path):
    """VTK's own Python reader: the vtkXMLUnstructuredGridReader that ParaView's reader wraps."""
    try:
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    except ImportError:
        sys.exit(3)
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    array = grid.GetCellData().GetArray("region")
    regions = [int(array.GetValue(i)) for i in range(array.GetNumberOfTuples())] if array else []
    tets = sum(1 for i in range(grid.GetNumberOfCells()) if grid.GetCellType(i) == 10)
    arrays = sorted(grid.GetCellData().GetArrayName(i) for i in range(grid.GetCellData().GetNumberOfArrays()))
    return {"tets": tets, "regions": regions, "arrays": arrays}


if __name__ == "__main__":
    mode = sys.argv[1] if sys.argv[1] in ("--paraview", "--vtk") else ""
    path = sys.argv[2] if mode else sys.argv[1]
    reader = {"--paraview": with_paraview, "--vtk": with_vtk, "": with_meshio}[mode]
    print(json.dumps(reader(path)))
