#include "capsubot/report/optimize_csv.hpp"

#include "capsubot/io/io.hpp"

namespace capsubot::text {

void WriteForceCsv(const Forcing& f, std::ostream& out) {
  out << "phi,F\n";  // phi = 0 is the impact
  for (int i = 0; i < kForceCsvRows; ++i) {
    const double phi = kTau * i / (kForceCsvRows - 1);
    out << FormatNumber(phi) << ',' << FormatNumber(f.F(phi)) << '\n';
  }
}

void WriteFromRestCsv(const MainJobResult& result, std::ostream& out) {
  out << "gait,row,mean_velocity,fraction,period,impacts_right,impacts_left,one_impact_orbit\n";
  const auto rows = [&](const char* gait, const Attractors& a) {
    for (const Attractor& at : a.attractors) {
      const Motion& m = at.motion;
      out << gait << ",attractor," << FormatNumber(at.mean_velocity) << ','
          << FormatNumber(at.fraction) << ',' << m.period << ',' << m.impacts_right << ','
          << m.impacts_left << ',' << (at.one_impact_orbit ? 1 : 0) << '\n';
    }
  };
  if (result.robust.found()) {
    out << "robust,promised," << FormatNumber(result.robust.solution.orbit.v_mean) << ",,1,1,0,1\n";
    rows("robust", result.reach.seed.from_rest.attractors);
  }
  rows("reach", result.reach.attractors);
}

}  // namespace capsubot::text
