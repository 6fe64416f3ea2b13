#pragma once
// Helpers of the Python module (docs/python.md): Python values <-> JSON, arguments converted with errors
// that name them, numpy arrays in and out, and the exception every bad input becomes (ochre.InputError, a
// ValueError, with the file and field in its message). The rules are those of docs/python.md, "Errors": a
// value of the wrong type raises TypeError naming the argument, a bad value InputError naming it.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace ochre {
struct ExrImage;
}

namespace ochre::python {

namespace py = pybind11;

// How deep Python containers may nest in a value converted to JSON (a scene, a material, a spectrum
// table): deeper values, and containers that hold themselves, are InputErrors naming the path.
inline constexpr int kMaxJsonDepth = 256;

// A Python value (dict, list, tuple, str, int, float, bool, None, numpy arrays and scalars) as JSON.
// `where` names the value, and errors name the path inside it in the scene's notation
// ("scene.shapes[0].radius"): TypeError for a value JSON cannot hold (an object, a non-str key),
// InputError for NaN or an infinity, an integer beyond 64 bits, text that is not valid Unicode, nesting
// deeper than kMaxJsonDepth or a container that holds itself.
nlohmann::json to_json(const py::handle& value, const std::string& where);
// JSON as Python values (strings that are not valid UTF-8 get U+FFFD).
py::object from_json(const nlohmann::json& value);
// A Python str of UTF-8 text; invalid bytes become U+FFFD (text read from files: EXR attributes, names).
py::str text(const std::string& utf8);

// "str 'abc'", "int 5", "float nan", "list": what an error says the caller gave (short, and never calling
// the value's own __repr__ but for built-in scalars).
std::string describe(const py::handle& value);
// Throws TypeError "NAME: expected EXPECTED, got DESCRIPTION" (cut as message_excerpt cuts long messages).
[[noreturn]] void wrong_type(const std::string& name, const std::string& expected, const py::handle& value);

// Arguments. Each throws TypeError naming `name` for a value of the wrong type and InputError naming it
// for a bad value (docs/python.md, "Errors").
// An integer (int or numpy integer; never bool, float or str) in [min, max].
long long integer_argument(const py::handle& value, const std::string& name, long long min, long long max);
std::uint64_t unsigned_argument(const py::handle& value, const std::string& name, std::uint64_t min = 0,
                                std::uint64_t max = UINT64_MAX);
// A real number (int, float or numpy number; never bool or str), finite.
double number_argument(const py::handle& value, const std::string& name);
// True or False (or a numpy bool): never 1, 0 or "yes", as booleans in a scene.
bool bool_argument(const py::handle& value, const std::string& name);
// A str, as UTF-8.
std::string string_argument(const py::handle& value, const std::string& name);
// A path: str, bytes or os.PathLike; not empty and without NUL characters. `expected` is what the
// TypeError says the argument takes.
std::filesystem::path path_argument(const py::handle& value, const std::string& name,
                                    const std::string& expected = "a path (str or os.PathLike)");
// base_dir of a scene or material given as a dict: an existing directory; the current directory for None.
std::filesystem::path base_dir_argument(const py::handle& value);
// A list, tuple or numpy array of exactly `count` items (InputError naming `name` for another length).
std::vector<py::object> items_argument(const py::handle& value, const std::string& name, size_t count,
                                       const std::string& expected);
// A callable or None.
py::object callable_argument(const py::handle& value, const std::string& name);

// A float64 array of any shape from an array-like of numbers (int, unsigned or float dtypes; never bool,
// str or object): TypeError naming `what` otherwise.
py::array_t<double, py::array::c_style | py::array::forcecast> number_array(const py::handle& value,
                                                                            const std::string& what);
// A float64 array of shape (n, 3) or (n,), C-contiguous (converted when needed); TypeError naming `what`
// when it is not an array of numbers, InputError when its shape is wrong.
py::array_t<double, py::array::c_style | py::array::forcecast> rows_of_3(const py::handle& value,
                                                                         const char* what);
py::array_t<double, py::array::c_style | py::array::forcecast> vector_of(const py::handle& value,
                                                                         const char* what);

// A new float32 numpy array of `shape` holding `values` (copied).
py::array_t<float> float_array(const std::vector<float>& values, const std::vector<py::ssize_t>& shape);

// (channels, attributes) of an image as ochre.read_exr returns them: every channel as (height, width)
// float32, the string attributes as str (bytes that are not UTF-8 become U+FFFD).
py::tuple exr_to_python(const ExrImage& image);

// Loads and ochre.relight record every file they read (spectra/input_file.h), so that their outputs never
// replace one. The log being recorded is process-wide and Python threads may read side by side, so each
// Recording is made under this mutex, taken with the GIL released. (A file another thread reads meanwhile,
// through read_exr or a material, is recorded too: the output then refuses it as well, which errs on the
// safe side.)
std::mutex& input_recording_mutex();

// Registers ochre.InputError; ochre's InputError, GraphError and ImageError raise it.
void register_errors(py::module_& m);

void register_scene(py::module_& m);
void register_material(py::module_& m);
void register_colour(py::module_& m);
void register_relight(py::module_& m);

}  // namespace ochre::python
