// The plain-text report of `capsubot continue` (docs/continuation.md).

#include "capsubot/report/continue_text.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace capsubot::text {
namespace {

std::string SwitchText(const SwitchResult& s, const std::string& name) {
  const bool grazing = s.point == SwitchPoint::kGrazing;
  if (!s.at) {
    return fmt::format("no {}: no branch to switch to\n",
                       grazing ? "grazing" : "located period doubling");
  }
  const std::string at = fmt::format(
      "the {} at {} = {:.12g}", grazing ? "grazing" : "period doubling", name, s.at->parameter);
  if (s.branch.status != ContinuationStatus::kOk) {
    return fmt::format("no branch to switch to at {}: {} ({})\n", at,
                       ContinuationStatusName(s.branch.status), s.branch.message);
  }
  return fmt::format("branch switched at {}\n{}", at, s.branch.Summary(name));
}

// How one direction of the curve ended, `at` its last point.
std::string CurveEndText(BranchEnd end, const std::string& at) {
  switch (end) {
    case BranchEnd::kRangeEnd:
      return "reached the edge of the range at " + at;
    case BranchEnd::kLost:
      return "lost at " + at + ": the corrector failed at the smallest step";
    case BranchEnd::kMaxPoints:
      return "stopped at " + at + ": the most points were reached";
    case BranchEnd::kEventChange:
      return "stopped at " + at + ": the motion's events change there";
    case BranchEnd::kNotRun:
    case BranchEnd::kGrazing:  // ends branches, never curves
    case BranchEnd::kHalfPeriod:
      break;
  }
  return "not followed";
}

std::string FollowText(const FollowResult& f, const std::string& name) {
  const Curve& c = f.curve;
  const char* type = SpecialPointTypeName(f.type);
  if (!f.at) return c.message + "\n";
  std::string t = fmt::format("curve of the {} at {} = {:.12g}, {} = {:.12g}, in ({}, {})\n", type,
                              name, f.at->parameter, f.param2, f.value2, name, f.param2);
  if (c.status != ContinuationStatus::kOk) {
    return t + fmt::format("  {} ({})\n", ContinuationStatusName(c.status), c.message);
  }
  const auto by = [](double CurvePoint::*field) {
    return [field](const CurvePoint& a, const CurvePoint& b) { return a.*field < b.*field; };
  };
  const auto [lo, hi] =
      std::minmax_element(c.points.begin(), c.points.end(), by(&CurvePoint::parameter));
  const auto [lo2, hi2] =
      std::minmax_element(c.points.begin(), c.points.end(), by(&CurvePoint::parameter2));
  t += fmt::format(
      "  curve          {} points over {} = {:.12g} .. {:.12g}, {} = {:.12g} .. {:.12g}\n",
      c.points.size(), name, lo->parameter, hi->parameter, f.param2, lo2->parameter2,
      hi2->parameter2);
  const auto at = [&](const CurvePoint& p) {
    return fmt::format("{} = {:.12g}, {} = {:.12g}", name, p.parameter, f.param2, p.parameter2);
  };
  t += fmt::format("  {:<14} {}\n", f.param2 + " falling",
                   CurveEndText(c.backward_end, at(c.points.front())));
  t += fmt::format("  {:<14} {}\n", f.param2 + " rising",
                   CurveEndText(c.forward_end, at(c.points.back())));
  return t;
}

}  // namespace

std::string ContinueJobText(const ContinueJobResult& r) {
  std::string t = r.branch.Summary(r.param);
  if (r.switched) t += SwitchText(*r.switched, r.param);
  if (r.follow) t += FollowText(*r.follow, r.param);
  return t;
}

}  // namespace capsubot::text
