// Engine exceptions as Python's (docs/python.md "Errors").
#include "bindings.h"

namespace raycast::python {

void bind_errors(py::module_& m) {
  static py::exception<SceneError> scene_error(m, "SceneError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SceneError& e) {
      py::object err = py::reinterpret_borrow<py::object>(scene_error.ptr())(e.what());
      err.attr("file") = e.file();
      err.attr("line") = e.line();
      err.attr("column") = e.column();
      err.attr("message") = e.message();
      PyErr_SetObject(scene_error.ptr(), err.ptr());
    } catch (const NotImplementedError& e) {
      PyErr_SetString(PyExc_NotImplementedError, e.what());
    } catch (const std::logic_error& e) {
      // invalid_argument and out_of_range keep pybind11's ValueError and IndexError.
      if (dynamic_cast<const std::invalid_argument*>(&e) ||
          dynamic_cast<const std::out_of_range*>(&e))
        throw;
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });
}

}  // namespace raycast::python
