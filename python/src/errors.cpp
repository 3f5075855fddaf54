// C++ errors as Python exceptions. Design note:
//
//   wtc.Error                       every error WTC raises (Exception)
//   wtc.InvalidInputError           bad input: wtc::InvalidInputError, whose
//                                   message names the file, line, column, key
//                                   and value (also a ValueError, so code that
//                                   catches ValueError for bad arguments
//                                   catches it)
//
// The message is the C++ one, unchanged. Any other std::exception from the
// library (a file system error, an engine's std::out_of_range) is wtc.Error
// with its message; Python exceptions raised in a Python controller pass
// through as they were raised.
#include <filesystem>

#include "bindings.hpp"
#include "wtc/base/error.hpp"

namespace wtc::python {

namespace {

// The two classes, alive as long as the process (never released: the
// translator may run until the interpreter ends).
PyObject* g_error = nullptr;
PyObject* g_invalid_input = nullptr;

PyObject* newException(const char* name, const char* doc, PyObject* bases) {
  PyObject* type = PyErr_NewExceptionWithDoc(name, doc, bases, nullptr);
  if (type == nullptr) throw py::error_already_set();
  return type;
}

}  // namespace

void bindErrors(py::module_& m) {
  g_error = newException("wtc.Error", "Every error WTC raises; the message is the C++ library's.", PyExc_Exception);
  const py::tuple bases = py::make_tuple(py::handle(g_error), py::handle(PyExc_ValueError));
  g_invalid_input = newException("wtc.InvalidInputError",
                                 "Bad input (also a ValueError): the message names the file, line, column, key and "
                                 "value.",
                                 bases.ptr());
  m.attr("Error") = py::handle(g_error);
  m.attr("InvalidInputError") = py::handle(g_invalid_input);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInputError& e) {
      PyErr_SetString(g_invalid_input, e.what());
    } catch (const py::error_already_set&) {
      throw;  // a Python exception (from a Python controller): as raised
    } catch (const py::builtin_exception&) {
      throw;  // pybind11's own: TypeError, IndexError, ...
    } catch (const std::bad_alloc&) {
      throw;  // MemoryError
    } catch (const std::exception& e) {
      PyErr_SetString(g_error, e.what());
    }
  });
}

}  // namespace wtc::python
