// The events and samples of a simulation as CSV rows.

#include "capsubot/report/simulate_csv.hpp"

#include "capsubot/io/io.hpp"

namespace capsubot::text {

SimulateCsv::SimulateCsv(std::ostream* events, std::ostream* trajectory)
    : events_(events), trajectory_(trajectory) {
  if (events_ != nullptr) *events_ << "phase,kind,x,u,v,y,u_before,v_before,mode\n";
  if (trajectory_ != nullptr) *trajectory_ << "phi,x,u,v,y,mode\n";
}

void SimulateCsv::OnEvent(const SimEvent& e) {
  if (events_ == nullptr) return;
  const SimState& s = e.after;
  *events_ << FormatNumber(s.phi) << ',' << EventKindName(e.kind) << ',' << FormatNumber(s.x) << ','
           << FormatNumber(s.u) << ',' << FormatNumber(s.v) << ',' << FormatNumber(s.y) << ','
           << FormatNumber(e.u_before) << ',' << FormatNumber(e.v_before) << ','
           << SimModeName(s.mode) << '\n';
}

void SimulateCsv::OnSample(const SimState& s) {
  if (trajectory_ == nullptr) return;
  *trajectory_ << FormatNumber(s.phi) << ',' << FormatNumber(s.x) << ',' << FormatNumber(s.u) << ','
               << FormatNumber(s.v) << ',' << FormatNumber(s.y) << ',' << SimModeName(s.mode)
               << '\n';
}

}  // namespace capsubot::text
