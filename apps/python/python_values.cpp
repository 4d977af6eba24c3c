#include "python_values.hpp"

#include <cmath>
#include <cstdint>

#include "errors.hpp"
#include "json_parse.hpp"

namespace dc::python {
namespace {

/// A key path one level deeper; a path past 160 characters ends in "..." (as parse_json_checked's).
std::string deeper(const std::string& key, const std::string& step) {
  if (key.size() > 160) return key.ends_with("...") ? key : key + "...";
  return key + step;
}

std::string member_path(const std::string& key, const std::string& name) {
  return key.empty() ? name : deeper(key, "." + name);
}

std::string element_path(const std::string& key, std::size_t index) {
  return deeper(key.empty() ? std::string("case") : key, "[" + std::to_string(index) + "]");
}

std::string where(const std::string& key) { return key.empty() ? "case" : key; }

std::string type_name(const py::handle& value) { return Py_TYPE(value.ptr())->tp_name; }

nlohmann::json finite_number(double v, const std::string& key) {
  if (std::isnan(v)) throw InputError(where(key), "is NaN; expected a finite number");
  if (!std::isfinite(v)) throw InputError(where(key), "is infinite; expected a finite number");
  return v;
}

/// A Python int: a JSON integer when it fits 64 bits, else a double (as a JSON parser reads a long
/// literal); InputError beyond the range of a double.
nlohmann::json integer(const py::handle& value, const std::string& key) {
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
  if (overflow == 0) {
    if (v == -1 && PyErr_Occurred()) throw py::error_already_set();
    return static_cast<std::int64_t>(v);
  }
  if (overflow > 0) {
    const unsigned long long u = PyLong_AsUnsignedLongLong(value.ptr());
    if (!PyErr_Occurred()) return static_cast<std::uint64_t>(u);
    PyErr_Clear();
  }
  const double d = PyLong_AsDouble(value.ptr());
  if (PyErr_Occurred()) {
    PyErr_Clear();
    throw InputError(where(key), "the integer is outside the range of a double");
  }
  return finite_number(d, key);
}

/// NumPy's types when NumPy is loaded (the module imports it at start; nullptr otherwise).
struct NumpyTypes {
  py::object ndarray, generic;
};

NumpyTypes numpy_types() {
  const py::dict modules = py::module_::import("sys").attr("modules");
  if (!modules.contains("numpy")) return {};
  const py::object np = modules["numpy"];
  return {np.attr("ndarray"), np.attr("generic")};
}

/// Whether a NumPy dtype holds plain numbers: bool, signed and unsigned integers, floating.
bool numeric_dtype(const py::handle& dtype) {
  const std::string kind = py::str(dtype.attr("kind"));
  return kind == "b" || kind == "i" || kind == "u" || kind == "f";
}

nlohmann::json walk(const py::handle& value, const std::string& key, int depth, const NumpyTypes& np);

nlohmann::json numpy_value(const py::handle& value, const std::string& key, int depth, const NumpyTypes& np) {
  if (!numeric_dtype(value.attr("dtype")))
    throw InputError(where(key), "a NumPy value of dtype " + py::str(value.attr("dtype")).cast<std::string>() +
                                     " cannot be read; expected numbers (bool, integer or floating dtype)");
  if (py::isinstance(value, np.generic)) return walk(value.attr("item")(), key, depth, np);
  const int ndim = value.attr("ndim").cast<int>();
  if (ndim > 2)
    throw InputError(where(key), "a NumPy array of " + std::to_string(ndim) +
                                     " dimensions cannot be read; expected one or two (a list, or a list of lists)");
  return walk(value.attr("tolist")(), key, depth, np);  // ndim 0: the scalar
}

nlohmann::json walk(const py::handle& value, const std::string& key, int depth, const NumpyTypes& np) {
  PyObject* o = value.ptr();
  if (value.is_none()) return nullptr;
  if (PyBool_Check(o)) return o == Py_True;
  if (PyLong_Check(o)) return integer(value, key);
  if (PyFloat_Check(o)) return finite_number(PyFloat_AsDouble(o), key);  // also NumPy's float64
  if (PyUnicode_Check(o)) return value.cast<std::string>();
  const bool dict = PyDict_Check(o), sequence = PyList_Check(o) || PyTuple_Check(o);
  if (dict || sequence) {
    if (depth >= case_json::kMaxJsonDepth)
      throw InputError(where(key), "nested more than " + std::to_string(case_json::kMaxJsonDepth) +
                                       " levels deep (lists and dicts); a case needs a few");
    if (sequence) {
      nlohmann::json out = nlohmann::json::array();
      std::size_t index = 0;
      for (const py::handle item : value) {
        out.push_back(walk(item, element_path(key, index), depth + 1, np));
        ++index;
      }
      return out;
    }
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [name, item] : py::reinterpret_borrow<py::dict>(value)) {
      if (!PyUnicode_Check(name.ptr()))
        throw InputError(where(key), "has the key " + py::repr(name).cast<std::string>() + " of type " +
                                         type_name(name) + "; keys must be strings");
      const std::string text = name.cast<std::string>();
      out[text] = walk(item, member_path(key, text), depth + 1, np);
    }
    return out;
  }
  if (np.ndarray && (py::isinstance(value, np.ndarray) || py::isinstance(value, np.generic)))
    return numpy_value(value, key, depth, np);
  if (py::hasattr(value, "__fspath__"))  // pathlib.Path and other paths: the file name
    return py::module_::import("os").attr("fsdecode")(value).cast<std::string>();
  throw InputError(where(key), "a value of type " + type_name(value) +
                                   " cannot be read; expected a number, a string, a bool, None, a list, a dict or "
                                   "a NumPy array (one or two dimensions)");
}

}  // namespace

nlohmann::json from_python(const py::handle& value, const std::string& key) {
  return walk(value, key, 0, numpy_types());
}

py::object to_python(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: {
      const double v = j.get<double>();
      return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none());
    }
    case nlohmann::json::value_t::string:
      return py::str(j.get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      py::list out(j.size());
      for (std::size_t k = 0; k < j.size(); ++k) out[k] = to_python(j[k]);
      return out;
    }
    case nlohmann::json::value_t::object: {
      py::dict out;
      for (const auto& [name, item] : j.items()) out[py::str(name)] = to_python(item);
      return out;
    }
    default:  // null, discarded, binary (a summary holds none)
      return py::none();
  }
}

}  // namespace dc::python
