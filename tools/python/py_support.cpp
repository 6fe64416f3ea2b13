#include "tools/python/py_support.h"

#include <fmt/format.h>

#include "materials/graph/graph_error.h"
#include "renderer/image/exr_writer.h"
#include "renderer/util/image_error.h"
#include "spectra/input_error.h"

namespace ochre::python {

nlohmann::json to_json(const py::handle& value, const std::string& where) {
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) {
    // Beyond 64 bits a Python integer is refused rather than wrapped.
    try {
      return value.cast<long long>();
    } catch (const py::cast_error&) {
      throw py::value_error(
          fmt::format("{}: the integer {} is out of range", where, py::str(value).cast<std::string>()));
    }
  }
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::array>(value) || py::hasattr(value, "dtype"))  // numpy arrays and scalars
    return to_json(value.attr("tolist")(), where);
  if (py::isinstance<py::dict>(value)) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& [key, item] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key))
        throw py::type_error(
            fmt::format("{}: keys must be strings, got {}", where, py::repr(key).cast<std::string>()));
      const std::string k = key.cast<std::string>();
      object[k] = to_json(item, fmt::format("{}['{}']", where, k));
    }
    return object;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    nlohmann::json array = nlohmann::json::array();
    size_t i = 0;
    for (const auto& item : value) array.push_back(to_json(item, fmt::format("{}[{}]", where, i++)));
    return array;
  }
  throw py::type_error(
      fmt::format("{}: cannot be written in a scene (a {}); use dict, list, str, int, float, "
                  "bool or None",
                  where, py::type::of(value).attr("__name__").cast<std::string>()));
}

py::object from_json(const nlohmann::json& value) {
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
      return py::str(value.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const auto& item : value) list.append(from_json(item));
      return list;
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items()) dict[py::str(key)] = from_json(item);
      return dict;
    }
    default:
      return py::none();
  }
}

std::filesystem::path to_path(const py::handle& value) {
  return py::module_::import("os").attr("fspath")(value).cast<std::string>();
}

py::array_t<double, py::array::c_style | py::array::forcecast> rows_of_3(const py::handle& value,
                                                                         const char* what) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!a) throw py::type_error(fmt::format("{}: expected an array of numbers", what));
  if (a.ndim() != 2 || a.shape(1) != 3) throw py::value_error(fmt::format("{}: expected shape (n, 3)", what));
  return a;
}

py::array_t<double, py::array::c_style | py::array::forcecast> vector_of(const py::handle& value,
                                                                         const char* what) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!a) throw py::type_error(fmt::format("{}: expected an array of numbers", what));
  if (a.ndim() != 1) throw py::value_error(fmt::format("{}: expected shape (n,)", what));
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
    channels[py::str(name)] = float_array(values, {image.height, image.width});
  py::dict attributes;
  for (const auto& [key, value] : image.string_attributes) attributes[py::str(key)] = value;
  return py::make_tuple(channels, attributes);
}

void register_errors(py::module_& m) {
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.doc() =
      "Bad input: a malformed scene or material, a missing file, an out-of-range or non-finite value. The "
      "message names the file and the field (the command line exits with code 2 on the same errors).";
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
