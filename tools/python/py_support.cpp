#include "tools/python/py_support.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "materials/graph/graph_error.h"
#include "renderer/image/exr_writer.h"
#include "renderer/util/image_error.h"
#include "spectra/input_error.h"

namespace ochre::python {

namespace {

// numpy's bool scalar: it converts to an integer and to a float, but is no number here (docs/python.md,
// "Errors": booleans are True or False, numbers are never booleans).
bool is_numpy_bool(PyObject* o) {
  const std::string_view type = Py_TYPE(o)->tp_name;
  return type == "numpy.bool_" || type == "numpy.bool";
}

bool is_numpy_value(const py::handle& value) {
  if (py::isinstance<py::array>(value)) return true;
  const py::object generic = py::module_::import("numpy").attr("generic");
  const int is = PyObject_IsInstance(value.ptr(), generic.ptr());
  if (is < 0) throw py::error_already_set();
  return is == 1;
}

// The Python error just raised when it is one a bad value raises (TypeError, ValueError, OverflowError,
// RecursionError): cleared, so that the caller raises its own naming the argument. Any other (an
// exception of the user's own code, KeyboardInterrupt) propagates.
void clear_value_error() {
  if (PyErr_ExceptionMatches(PyExc_TypeError) || PyErr_ExceptionMatches(PyExc_ValueError) ||
      PyErr_ExceptionMatches(PyExc_OverflowError) || PyErr_ExceptionMatches(PyExc_RecursionError)) {
    PyErr_Clear();
    return;
  }
  throw py::error_already_set();
}

// The decimal digits of a Python int, or "an integer of N bits" beyond 200 bits (Python itself refuses
// to print integers of more than 4300 digits).
std::string integer_text(PyObject* o) {
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(o, &overflow);
  if (!overflow && !(v == -1 && PyErr_Occurred())) return std::to_string(v);
  PyErr_Clear();
  const size_t bits = _PyLong_NumBits(o);
  if (bits == static_cast<size_t>(-1)) PyErr_Clear();
  if (bits <= 200) {
    PyObject* s = PyLong_Type.tp_repr(o);
    if (s) {
      const char* utf8 = PyUnicode_AsUTF8(s);
      std::string result = utf8 ? utf8 : "";
      Py_DECREF(s);
      if (!result.empty()) return result;
    }
    PyErr_Clear();
  }
  return fmt::format("{}an integer of {} bits", overflow < 0 ? "minus " : "", bits);
}

// The UTF-8 of a str; nullopt (no Python error left) when it holds lone surrogates.
std::optional<std::string> utf8_of(PyObject* o) {
  Py_ssize_t size = 0;
  const char* data = PyUnicode_AsUTF8AndSize(o, &size);
  if (!data) {
    PyErr_Clear();
    return std::nullopt;
  }
  return std::string(data, static_cast<size_t>(size));
}

// The path to a value inside the value being converted to JSON, in the scene's notation.
struct JsonPath {
  struct Step {
    bool index = false;
    size_t position = 0;
    std::string key;
  };
  std::string root;
  std::vector<Step> steps;
  // The containers being converted, with the number of steps to each (for "refers to itself").
  std::vector<std::pair<PyObject*, size_t>> open;

  // The first `count` steps ("scene.materials.a[0]"); long paths show their first 8 steps then "...".
  std::string text(size_t count) const {
    std::string s = root;
    for (size_t i = 0; i < count && i < steps.size(); ++i) {
      if (i == 8 && count > 10) return s + "...";
      s += steps[i].index ? fmt::format("[{}]", steps[i].position) : "." + steps[i].key;
    }
    return s;
  }
  std::string text() const { return text(steps.size()); }
};

// Pops what a container pushed onto the path when its conversion ends (or throws).
struct Entered {
  JsonPath& path;
  explicit Entered(JsonPath& p, PyObject* container) : path(p) {
    path.open.emplace_back(container, path.steps.size());
  }
  ~Entered() { path.open.pop_back(); }
};

struct Step {
  JsonPath& path;
  Step(JsonPath& p, JsonPath::Step step) : path(p) { path.steps.push_back(std::move(step)); }
  ~Step() { path.steps.pop_back(); }
};

nlohmann::json convert(const py::handle& value, JsonPath& path) {
  PyObject* o = value.ptr();
  if (o == Py_None) return nullptr;
  if (PyBool_Check(o)) return o == Py_True;
  if (PyLong_Check(o)) {
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(o, &overflow);
    if (!overflow && !(v == -1 && PyErr_Occurred())) return v;
    PyErr_Clear();
    if (overflow > 0) {
      const unsigned long long u = PyLong_AsUnsignedLongLong(o);
      if (!(u == static_cast<unsigned long long>(-1) && PyErr_Occurred())) return u;
      PyErr_Clear();
    }
    throw InputError(fmt::format("{}: the integer {} is out of range (JSON integers have 64 bits)",
                                 path.text(), integer_text(o)));
  }
  if (PyFloat_Check(o)) {
    const double d = PyFloat_AS_DOUBLE(o);
    if (!std::isfinite(d))
      throw InputError(fmt::format("{}: {} is not a number JSON can hold (NaN and infinities are refused)",
                                   path.text(), d));
    return d;
  }
  if (PyUnicode_Check(o)) {
    std::optional<std::string> s = utf8_of(o);
    if (!s) throw InputError(path.text() + ": the text is not valid Unicode (it holds a lone surrogate)");
    return std::move(*s);
  }
  const bool dict = PyDict_Check(o), sequence = PyList_Check(o) || PyTuple_Check(o);
  const bool numpy = !dict && !sequence && is_numpy_value(value);
  if (!dict && !sequence && !numpy)
    throw py::type_error(
        message_excerpt(fmt::format("{}: cannot be written in a scene (type {}); use dict, list, str, int, "
                                    "float, bool or None",
                                    path.text(), Py_TYPE(o)->tp_name)));
  for (const auto& [container, steps] : path.open)
    if (container == o)
      throw InputError(
          fmt::format("{}: refers to itself (it is {}, which contains it)", path.text(), path.text(steps)));
  if (path.steps.size() >= static_cast<size_t>(kMaxJsonDepth))
    throw InputError(fmt::format("{}: nested deeper than {} levels", path.text(), kMaxJsonDepth));
  const Entered entered(path, o);
  if (numpy) return convert(value.attr("tolist")(), path);  // numbers and lists; object arrays hold anything
  if (dict) {
    // A snapshot of the items, so that nothing the conversion does can change what is iterated.
    const py::list items = py::reinterpret_steal<py::list>(PyDict_Items(o));
    if (!items) throw py::error_already_set();
    nlohmann::json object = nlohmann::json::object();
    for (const py::handle item : items) {
      const py::handle key = PyTuple_GET_ITEM(item.ptr(), 0);
      if (!PyUnicode_Check(key.ptr()))
        throw py::type_error(
            message_excerpt(fmt::format("{}: keys must be strings, got {}", path.text(), describe(key))));
      std::optional<std::string> k = utf8_of(key.ptr());
      if (!k) throw InputError(path.text() + ": a key is not valid Unicode text (it holds a lone surrogate)");
      const Step step(path, {false, 0, *k});
      object[*k] = convert(PyTuple_GET_ITEM(item.ptr(), 1), path);
    }
    return object;
  }
  const py::tuple items = py::reinterpret_steal<py::tuple>(PySequence_Tuple(o));
  if (!items) throw py::error_already_set();
  nlohmann::json array = nlohmann::json::array();
  for (size_t i = 0; i < items.size(); ++i) {
    const Step step(path, {true, i, {}});
    array.push_back(convert(items[i], path));
  }
  return array;
}

py::object from_json_at(const nlohmann::json& value, int depth) {
  if (depth > kMaxJsonDepth)
    throw InputError(fmt::format("a value nested deeper than {} levels cannot be returned", kMaxJsonDepth));
  switch (value.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(value.get<long long>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(value.get<unsigned long long>());
    case nlohmann::json::value_t::number_float:
      return py::float_(value.get<double>());
    case nlohmann::json::value_t::string:
      return text(value.get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const auto& item : value) list.append(from_json_at(item, depth + 1));
      return list;
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items()) dict[text(key)] = from_json_at(item, depth + 1);
      return dict;
    }
    default:
      return py::none();
  }
}

}  // namespace

py::array_t<double, py::array::c_style | py::array::forcecast> number_array(const py::handle& value,
                                                                            const std::string& what) {
  py::object array;
  if (py::isinstance<py::array>(value)) {
    array = py::reinterpret_borrow<py::object>(value);
  } else {
    PyObject* converted =
        PyObject_CallOneArg(py::module_::import("numpy").attr("asarray").ptr(), value.ptr());
    if (!converted) {
      clear_value_error();
      wrong_type(what, "an array of numbers", value);
    }
    array = py::reinterpret_steal<py::object>(converted);
  }
  const char kind = py::reinterpret_borrow<py::array>(array).dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'f') wrong_type(what, "an array of numbers", value);
  auto numbers = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!numbers) wrong_type(what, "an array of numbers", value);
  return numbers;
}

nlohmann::json to_json(const py::handle& value, const std::string& where) {
  JsonPath path;
  path.root = where;
  return convert(value, path);
}

py::object from_json(const nlohmann::json& value) {
  return from_json_at(value, 0);
}

py::str text(const std::string& utf8) {
  PyObject* s = PyUnicode_DecodeUTF8(utf8.data(), static_cast<Py_ssize_t>(utf8.size()), "replace");
  if (!s) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(s);
}

std::string describe(const py::handle& value) {
  PyObject* o = value.ptr();
  if (o == Py_None) return "None";
  if (PyBool_Check(o)) return o == Py_True ? "bool True" : "bool False";
  const std::string type = Py_TYPE(o)->tp_name;
  if (PyLong_Check(o)) return type + " " + integer_text(o);
  if (PyFloat_Check(o)) return fmt::format("{} {}", type, PyFloat_AS_DOUBLE(o));
  if (PyUnicode_Check(o)) {
    // The repr of (the start of) an exact str: built-in, and printable whatever the text holds.
    const Py_ssize_t length = PyUnicode_GET_LENGTH(o);
    const py::object start =
        py::reinterpret_steal<py::object>(PyUnicode_Substring(o, 0, std::min<Py_ssize_t>(length, 40)));
    if (!start) {
      PyErr_Clear();
      return type;
    }
    const py::object repr = py::reinterpret_steal<py::object>(PyUnicode_Type.tp_repr(start.ptr()));
    const std::optional<std::string> r = repr ? utf8_of(repr.ptr()) : std::nullopt;
    PyErr_Clear();
    return type + " " + r.value_or("") + (length > 40 ? "..." : "");
  }
  return type;
}

void wrong_type(const std::string& name, const std::string& expected, const py::handle& value) {
  throw py::type_error(
      message_excerpt(fmt::format("{}: expected {}, got {}", name, expected, describe(value))));
}

namespace {

// A Python int from an int or an object with __index__ (numpy integers); TypeError naming the argument for
// anything else.
py::int_ integer_of(const py::handle& value, const std::string& name) {
  PyObject* o = value.ptr();
  if (PyBool_Check(o) || is_numpy_bool(o) || PyFloat_Check(o) || PyUnicode_Check(o) || PyBytes_Check(o))
    wrong_type(name, "an integer", value);
  if (PyLong_Check(o)) return py::reinterpret_borrow<py::int_>(o);
  if (Py_TYPE(o)->tp_as_number && Py_TYPE(o)->tp_as_number->nb_index) {
    PyObject* index = PyNumber_Index(o);
    if (index) return py::reinterpret_steal<py::int_>(index);
    clear_value_error();
  }
  wrong_type(name, "an integer", value);
}

}  // namespace

long long integer_argument(const py::handle& value, const std::string& name, long long min, long long max) {
  const py::int_ v = integer_of(value, name);
  int overflow = 0;
  const long long r = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
  if (r == -1 && PyErr_Occurred()) PyErr_Clear();
  if (overflow || r < min || r > max)
    throw InputError(fmt::format("{}: must be in [{}, {}] (got {})", name, min, max, integer_text(v.ptr())));
  return r;
}

std::uint64_t unsigned_argument(const py::handle& value, const std::string& name, std::uint64_t min,
                                std::uint64_t max) {
  const py::int_ v = integer_of(value, name);
  const unsigned long long r = PyLong_AsUnsignedLongLong(v.ptr());  // fails for negative and too large
  const bool failed = r == static_cast<unsigned long long>(-1) && PyErr_Occurred();
  if (failed) PyErr_Clear();
  if (failed || r < min || r > max)
    throw InputError(fmt::format("{}: must be in [{}, {}] (got {})", name, min,
                                 max == UINT64_MAX ? "2^64 - 1" : std::to_string(max),
                                 integer_text(v.ptr())));
  return r;
}

double number_argument(const py::handle& value, const std::string& name) {
  PyObject* o = value.ptr();
  if (PyBool_Check(o) || is_numpy_bool(o) || PyUnicode_Check(o) || PyBytes_Check(o))
    wrong_type(name, "a number", value);
  double d = 0.0;
  if (PyFloat_Check(o)) {
    d = PyFloat_AS_DOUBLE(o);
  } else if (PyLong_Check(o)) {
    d = PyLong_AsDouble(o);
    if (d == -1.0 && PyErr_Occurred()) {
      PyErr_Clear();
      throw InputError(fmt::format("{}: must be a finite number (got {})", name, integer_text(o)));
    }
  } else {
    PyNumberMethods* number = Py_TYPE(o)->tp_as_number;
    if (!number || (!number->nb_float && !number->nb_index)) wrong_type(name, "a number", value);
    PyObject* f = PyNumber_Float(o);
    if (!f) {
      clear_value_error();
      wrong_type(name, "a number", value);
    }
    d = PyFloat_AsDouble(f);
    Py_DECREF(f);
  }
  if (!std::isfinite(d)) throw InputError(fmt::format("{}: must be a finite number (got {})", name, d));
  return d;
}

bool bool_argument(const py::handle& value, const std::string& name) {
  PyObject* o = value.ptr();
  if (PyBool_Check(o)) return o == Py_True;
  if (is_numpy_bool(o)) {
    const int truth = PyObject_IsTrue(o);
    if (truth < 0) throw py::error_already_set();
    return truth == 1;
  }
  wrong_type(name, "True or False", value);
}

std::string string_argument(const py::handle& value, const std::string& name) {
  if (!PyUnicode_Check(value.ptr())) wrong_type(name, "a str", value);
  std::optional<std::string> s = utf8_of(value.ptr());
  if (!s) throw InputError(name + ": the text is not valid Unicode (it holds a lone surrogate)");
  return std::move(*s);
}

std::filesystem::path path_argument(const py::handle& value, const std::string& name,
                                    const std::string& expected) {
  py::object path;
  if (PyUnicode_Check(value.ptr()) || PyBytes_Check(value.ptr())) {
    path = py::reinterpret_borrow<py::object>(value);
  } else {
    PyObject* fspath = PyOS_FSPath(value.ptr());  // os.fspath: str or bytes from an os.PathLike
    if (!fspath) {
      clear_value_error();
      wrong_type(name, expected, value);
    }
    path = py::reinterpret_steal<py::object>(fspath);
  }
  if (PyBytes_Check(path.ptr())) {
    PyObject* decoded =
        PyUnicode_DecodeFSDefaultAndSize(PyBytes_AS_STRING(path.ptr()), PyBytes_GET_SIZE(path.ptr()));
    if (!decoded) throw py::error_already_set();
    path = py::reinterpret_steal<py::object>(decoded);
  }
  std::optional<std::string> s = utf8_of(path.ptr());
  if (!s) throw InputError(name + ": the path is not valid UTF-8");
  if (s->empty()) throw InputError(name + ": the path is empty");
  if (s->find('\0') != std::string::npos) throw InputError(name + ": the path contains a NUL character");
  return *s;
}

std::filesystem::path base_dir_argument(const py::handle& value) {
  std::error_code error;
  if (value.is_none()) {
    std::filesystem::path current = std::filesystem::current_path(error);
    if (error)
      throw InputError("base_dir: the current directory cannot be read (" + error.message() + "); give one");
    return current;
  }
  const std::filesystem::path dir = path_argument(value, "base_dir");
  if (!std::filesystem::is_directory(dir, error))
    throw InputError(fmt::format("base_dir: {} is not a directory", dir.string()));
  return dir;
}

std::vector<py::object> items_argument(const py::handle& value, const std::string& name, size_t count,
                                       const std::string& expected) {
  py::object sequence;
  if (PyList_Check(value.ptr()) || PyTuple_Check(value.ptr()))
    sequence = py::reinterpret_steal<py::object>(PySequence_Tuple(value.ptr()));
  else if (py::isinstance<py::array>(value) && py::reinterpret_borrow<py::array>(value).ndim() >= 1)
    sequence = value.attr("tolist")();
  else
    wrong_type(name, expected, value);
  if (!sequence) throw py::error_already_set();
  const Py_ssize_t n = PySequence_Size(sequence.ptr());
  if (n < 0) throw py::error_already_set();
  if (static_cast<size_t>(n) != count)
    throw InputError(fmt::format("{}: expected {}, got {} item{}", name, expected, n, n == 1 ? "" : "s"));
  std::vector<py::object> items;
  for (Py_ssize_t i = 0; i < n; ++i) {
    PyObject* item = PySequence_GetItem(sequence.ptr(), i);
    if (!item) throw py::error_already_set();
    items.push_back(py::reinterpret_steal<py::object>(item));
  }
  return items;
}

py::object callable_argument(const py::handle& value, const std::string& name) {
  if (!value.is_none() && !PyCallable_Check(value.ptr())) wrong_type(name, "a callable or None", value);
  return py::reinterpret_borrow<py::object>(value);
}

py::array_t<double, py::array::c_style | py::array::forcecast> rows_of_3(const py::handle& value,
                                                                         const char* what) {
  auto a = number_array(value, what);
  if (a.ndim() != 2 || a.shape(1) != 3) throw InputError(fmt::format("{}: expected shape (n, 3)", what));
  return a;
}

py::array_t<double, py::array::c_style | py::array::forcecast> vector_of(const py::handle& value,
                                                                         const char* what) {
  auto a = number_array(value, what);
  if (a.ndim() != 1) throw InputError(fmt::format("{}: expected shape (n,)", what));
  return a;
}

py::array_t<float> float_array(const std::vector<float>& values, const std::vector<py::ssize_t>& shape) {
  py::array_t<float> a(shape);
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

py::tuple exr_to_python(const ExrImage& image) {
  py::dict channels;
  for (const auto& [name, values] : image.channels)
    channels[text(name)] = float_array(values, {image.height, image.width});
  py::dict attributes;
  for (const auto& [key, value] : image.string_attributes) attributes[text(key)] = text(value);
  return py::make_tuple(channels, attributes);
}

std::mutex& input_recording_mutex() {
  static std::mutex mutex;
  return mutex;
}

void register_errors(py::module_& m) {
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.doc() =
      "Bad input: a malformed scene or material, a missing file, an out-of-range or non-finite value, an "
      "output that would replace an input, a link or a device. The message names the argument, or the file "
      "and the field (the command line exits with code 2 on the same errors). A value of the wrong type "
      "raises TypeError naming the argument (docs/python.md, \"Errors\").";
  m.def(
      "_describe", [](const py::object& value) { return describe(value); }, py::arg("value"),
      "What an error message says a value is (\"str 'x'\", \"int 5\", \"list\")");
  // Messages are cut like the command line's (message_excerpt): a file's 50 MB value is not quoted whole.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      input_error(message_excerpt(e.what()).c_str());
    } catch (const GraphError& e) {
      input_error(message_excerpt(e.what()).c_str());
    } catch (const ImageError& e) {
      input_error(message_excerpt(e.what()).c_str());
    }
  });
}

}  // namespace ochre::python
