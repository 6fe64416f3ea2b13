#pragma once
// Helpers of the Python module (docs/python.md): Python values <-> JSON, numpy arrays in and out, and the
// exception every bad input becomes (ochre.InputError, a ValueError, with the file and field in its
// message).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ochre {
struct ExrImage;
}

namespace ochre::python {

namespace py = pybind11;

// A Python value (dict, list, tuple, str, int, float, bool, None, numpy arrays and scalars) as JSON;
// `where` names it in the TypeError raised for anything else ("scene['shapes'][0]").
nlohmann::json to_json(const py::handle& value, const std::string& where);
// JSON as Python values.
py::object from_json(const nlohmann::json& value);

// A path-like Python value (str or os.PathLike) as a path.
std::filesystem::path to_path(const py::handle& value);

// A float64 array of shape (n, 3) or (n,), C-contiguous (converted when needed); a TypeError / ValueError
// names `what` when the shape is wrong.
py::array_t<double, py::array::c_style | py::array::forcecast> rows_of_3(const py::handle& value,
                                                                         const char* what);
py::array_t<double, py::array::c_style | py::array::forcecast> vector_of(const py::handle& value,
                                                                         const char* what);

// A new float32 numpy array of `shape` holding `values` (copied).
py::array_t<float> float_array(const std::vector<float>& values, const std::vector<py::ssize_t>& shape);

// (channels, attributes) of an image as ochre.read_exr returns them: every channel as (height, width)
// float32, the string attributes as str.
py::tuple exr_to_python(const ExrImage& image);

// Registers ochre.InputError; ochre's InputError, GraphError and ImageError raise it.
void register_errors(py::module_& m);

void register_scene(py::module_& m);
void register_material(py::module_& m);
void register_colour(py::module_& m);
void register_relight(py::module_& m);

}  // namespace ochre::python
