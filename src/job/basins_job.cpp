// capsubot basins as one call: the map of starts of a plane.

#include "capsubot/job/basins_job.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "capsubot/numerics/grid_value.hpp"
#include "start_map_run.hpp"

namespace capsubot {

namespace {

void CheckVelocityRange(const VelocityPlane& p, const SettingNames& names) {
  if (!(p.u_min < p.u_max)) {
    throw std::invalid_argument(fmt::format("{} = {} and {} = {} are invalid: expected {} < {}",
                                            names.Name("u_min"), p.u_min, names.Name("u_max"),
                                            p.u_max, names.InRule("u_min"), names.InRule("u_max")));
  }
}

}  // namespace

void BasinsJobOptions::Validate() const {
  if (const auto* p = std::get_if<VelocityPlane>(&plane)) CheckVelocityRange(*p, {});
  map.Validate();
}

StartPlane StartPlaneNamed(const std::string& name, const VelocityPlane& velocity,
                           const SettingNames& names) {
  const bool x0_u0 = name == StartPlaneName(velocity);
  if (!x0_u0 && name != StartPlaneName(RestPlane{})) {
    throw std::invalid_argument(
        fmt::format("{} = {} is invalid: expected x0-psi or x0-u0", names.Name("plane"), name));
  }
  CheckVelocityRange(velocity, names);
  return x0_u0 ? StartPlane(velocity) : StartPlane(RestPlane{});
}

const char* StartPlaneName(const StartPlane& plane) {
  return std::holds_alternative<VelocityPlane>(plane) ? "x0-u0" : "x0-psi";
}

std::vector<PhaseState> BasinStarts(const BasinsJobOptions& options) {
  const int nx = options.map.starts.n_x;
  const int ny = options.map.starts.n_psi;
  std::vector<PhaseState> starts = GridStarts(nx, ny);
  const auto* p = std::get_if<VelocityPlane>(&options.plane);
  if (p == nullptr) return starts;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      PhaseState& s = starts[static_cast<std::size_t>(i) * static_cast<std::size_t>(ny) +
                             static_cast<std::size_t>(j)];
      s = RestStart((i + 0.5) / nx, p->psi);
      // Cell centres: the odd values of the grid of 2 ny + 1 values over [u_min, u_max].
      s.u = GridValue(p->u_min, p->u_max, 2 * std::int64_t{ny} + 1, 2 * std::int64_t{j} + 1);
    }
  }
  return starts;
}

BasinsJobResult RunBasinsJob(const BasinsJobOptions& options) {
  options.Validate();
  BasinsJobResult result;
  result.plane = options.plane;
  result.map = detail::RunStartMap(options.map, BasinStarts(options),
                                   std::holds_alternative<VelocityPlane>(options.plane), "basins");
  return result;
}

StartMapWork BasinsJobWork(const BasinsJobOptions& options) {
  return detail::StartMapWorkOf(options.map, BasinStarts(options));
}

}  // namespace capsubot
