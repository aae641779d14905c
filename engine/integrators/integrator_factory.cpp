#include "integrators/integrator_factory.h"

#include "core/error.h"
#include "integrators/cvode_integrator.h"
#include "integrators/rodas4.h"
#include "integrators/w_method.h"

namespace pat {

std::unique_ptr<Integrator> make_integrator(const std::string& name,
                                            const IntegratorOptions& options) {
  if (name == "w2") return std::make_unique<WMethod2>(options);
  if (name == "rodas") return std::make_unique<Rodas4>(options);
  if (name == "cvode") return std::make_unique<CvodeIntegrator>(options);
  throw InputError("unknown integrator '" + name + "' (expected w2, rodas or cvode)");
}

}  // namespace pat
