"""VTK files read back as ParaView's Python opens them (python3-vtk9; the test is skipped without it)."""
import pytest


def read_vti(path):
    """A .vti through VTK's XML reader: the image and its point arrays by name (NumPy)."""
    vtk = pytest.importorskip("vtk")
    from vtk.util.numpy_support import vtk_to_numpy

    reader = vtk.vtkXMLImageDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    image = reader.GetOutput()
    data = image.GetPointData()
    arrays = {data.GetArrayName(k): vtk_to_numpy(data.GetArray(k)) for k in range(data.GetNumberOfArrays())}
    return image, arrays
