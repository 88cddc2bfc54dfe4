#include "rstruct/poles/ball_parameters.hpp"

#include <cmath>
#include <sstream>

#include "rstruct/core/error.hpp"

namespace rstruct::poles {
namespace {

void require_finite_non_negative(double value, const char* name) {
  if (!std::isfinite(value) || value < 0) {
    std::ostringstream message;
    message << "parameter " << name << " = " << value
            << " is invalid: it must be a finite number >= 0";
    throw InvalidInput(message.str());
  }
}

}  // namespace

ParameterCheck check_ball_parameters(const BallParameters& parameters) {
  require_finite_non_negative(parameters.rho, "rho");
  require_finite_non_negative(parameters.rho_tilde, "rho_tilde");
  require_finite_non_negative(parameters.eps, "eps");
  if (parameters.rho == 0) {
    throw InvalidInput("parameter rho = 0 is invalid: surface balls need a positive radius");
  }
  ParameterCheck check;
  auto warn = [&check](const std::string& text) { check.warnings.push_back(text); };
  if (parameters.rho < kRhoMin || parameters.rho > kRhoMax) {
    std::ostringstream text;
    text << "rho = " << parameters.rho << " lies outside [" << kRhoMin << ", " << kRhoMax
         << "]: the topology guarantee of Lemma 5.6 no longer holds";
    warn(text.str());
  }
  if (parameters.rho_tilde > kRhoTildeMax) {
    std::ostringstream text;
    text << "rho_tilde = " << parameters.rho_tilde << " exceeds " << kRhoTildeMax
         << ": the topology guarantee of Theorem 6.1 no longer holds";
    warn(text.str());
  }
  if (parameters.rho_tilde >= parameters.rho) {
    std::ostringstream text;
    text << "rho_tilde = " << parameters.rho_tilde << " is not smaller than rho = "
         << parameters.rho << ": Theorem 6.1 needs rho_tilde < rho";
    warn(text.str());
  }
  return check;
}

double absolute_eps(const BallParameters& parameters, double bbox_diagonal) {
  require_finite_non_negative(parameters.eps, "eps");
  if (!parameters.eps_relative) return parameters.eps;
  require_finite_non_negative(bbox_diagonal, "bounding-box diagonal");
  return parameters.eps * bbox_diagonal;
}

}  // namespace rstruct::poles
