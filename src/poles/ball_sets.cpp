#include "rstruct/poles/ball_sets.hpp"

#include <cmath>
#include <sstream>

#include "rstruct/core/error.hpp"

namespace rstruct::poles {

std::vector<Ball> scaled_sample_balls(std::span<const Point3> samples,
                                      std::span<const double> dhat, double factor) {
  if (samples.size() != dhat.size()) {
    throw InvalidInput("ball sets: " + std::to_string(samples.size()) + " samples but " +
                       std::to_string(dhat.size()) + " pole distances");
  }
  if (!std::isfinite(factor) || factor < 0) {
    std::ostringstream message;
    message << "ball sets: radius factor " << factor << " must be finite and >= 0";
    throw InvalidInput(message.str());
  }
  std::vector<Ball> balls(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!std::isfinite(dhat[i]) || dhat[i] < 0) {
      std::ostringstream message;
      message << "ball sets: pole distance of sample " << i << " is " << dhat[i];
      throw InvalidInput(message.str());
    }
    balls[i] = Ball{samples[i], factor * dhat[i]};
  }
  return balls;
}

PolarBalls inner_polar_balls(const PoleSet& poles, double eps) {
  if (!std::isfinite(eps) || eps < 0) {
    std::ostringstream message;
    message << "ball sets: polar ball enlargement eps = " << eps << " must be finite and >= 0";
    throw InvalidInput(message.str());
  }
  PolarBalls result;
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    if (poles.label[p] != PoleLabel::inner) continue;
    result.balls.push_back(Ball{poles.centre[p], poles.radius[p] + eps});
    result.pole.push_back(p);
  }
  return result;
}

}  // namespace rstruct::poles
