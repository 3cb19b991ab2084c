// The compiled extension subdiv._subdiv. Import the package `subdiv`, not
// this module: python/subdiv/__init__.py is the documented API.

#include "bindings.h"
#include "subdiv/version.h"

PYBIND11_MODULE(_subdiv, m) {
  using namespace subdiv::python;
  m.doc() = "subdiv's compiled core; use the package `subdiv`.";
  m.attr("__version__") = subdiv::version();
  bind_errors(m);
  bind_mesh(m);
  bind_schemes(m);
  bind_refine(m);
  bind_analysis(m);
  bind_depth(m);
  bind_curves(m);
}
