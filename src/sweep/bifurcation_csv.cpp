// The CSV files of a bifurcation diagram and the resumable files of a shard of a study.

#include "capsubot/sweep/bifurcation_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "capsubot/io/io.hpp"
#include "capsubot/sweep/bifurcation_shards.hpp"
#include "sweep/sweep_file.hpp"

namespace capsubot {
namespace {

// The name of the first column with a second parameter, with its comma ("" without).
std::string OverColumn(const BifurcationOptions& o) {
  if (o.over_values.empty()) return "";
  return ModelParameterName(o.over, o.over_harmonic) + ',';
}

// The cell of the second parameter before a row ("" without it).
std::string OverCell(bool over, double value) { return over ? FormatNumber(value) + ',' : ""; }

// One file of a shard: the lines before its rows, the record its checkpoint keeps, its rows
// and their count in a part.
struct ShardTarget {
  std::string path, head, description;
  void (*append)(std::string&, const BifurcationDiagram&, bool);
  std::size_t (*rows)(const BifurcationDiagram&);
};

}  // namespace

std::string BifurcationImpactsHeader(const BifurcationOptions& options) {
  return OverColumn(options) + "param,direction,period_index,wall,phase,velocity\n";
}

std::string BifurcationSummaryHeader(const BifurcationOptions& options) {
  return OverColumn(options) +
         "param,direction,period,impacts_right,impacts_left,mean_velocity,largest_multiplier,"
         "largest_multiplier_im,spectral_radius,status\n";
}

void AppendImpactRows(std::string& out, const BifurcationDiagram& d, bool over) {
  for (const ImpactPoint& p : d.impacts) {
    out += OverCell(over, p.over);
    out += fmt::format("{},{},{},{},{},{}\n", FormatNumber(p.param),
                       SweepDirectionName(p.direction), p.period_index, p.right ? "right" : "left",
                       FormatNumber(p.phase), FormatNumber(p.velocity));
  }
}

void AppendSummaryRows(std::string& out, const BifurcationDiagram& d, bool over) {
  for (const BifurcationPoint& p : d.summary) {
    out += OverCell(over, p.over);
    out += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", FormatNumber(p.param),
                       SweepDirectionName(p.direction), p.motion.period, p.motion.impacts_right,
                       p.motion.impacts_left, FormatNumber(p.motion.mean_velocity),
                       FormatNumber(p.multiplier_re), FormatNumber(p.multiplier_im),
                       FormatNumber(p.spectral_radius), MotionStatusName(p.motion.status));
  }
}

void BifurcationShardFiles::Validate() const {
  if (impacts.empty()) {
    throw std::invalid_argument("impacts is missing: expected the path of the impacts CSV");
  }
  if (summary == impacts) {
    throw std::invalid_argument(fmt::format(
        "summary = {} is invalid: expected a file other than the impacts CSV", summary));
  }
  if (!(checkpoint_seconds >= 0.0) || !std::isfinite(checkpoint_seconds)) {
    throw std::invalid_argument(fmt::format(
        "checkpoint_seconds = {} is invalid: expected a finite time >= 0", checkpoint_seconds));
  }
}

BifurcationShardSummary WriteBifurcationShard(const RobotModel& robot,
                                              const BifurcationOptions& options,
                                              const BifurcationShardFiles& files,
                                              const StartsProgress& progress,
                                              const BlockBackend& backend) {
  files.Validate();
  ValidateBifurcation(robot, options);
  const bool over = !options.over_values.empty();
  const std::string lines =
      files.comments + fmt::format("# shard {}/{} of {} continuations\n", options.shard,
                                   options.shards, BifurcationContinuations(options));
  std::vector<ShardTarget> targets;
  targets.push_back({files.impacts, lines + BifurcationImpactsHeader(options), "", AppendImpactRows,
                     [](const BifurcationDiagram& d) { return d.impacts.size(); }});
  if (!files.summary.empty()) {
    targets.push_back({files.summary, lines + BifurcationSummaryHeader(options), "",
                       AppendSummaryRows,
                       [](const BifurcationDiagram& d) { return d.summary.size(); }});
  }
  for (ShardTarget& t : targets) {
    // One line: what determines the bytes (the part count tells whether analytic parts are).
    t.description =
        fmt::format("bifurcation shard of {} parts {}", BifurcationParts(options), t.head);
    std::replace(t.description.begin(), t.description.end(), '\n', '\x1f');
    if (files.resume) detail::SweepFile::CheckResume(t.path, t.description, "shard");
  }
  std::vector<std::unique_ptr<detail::SweepFile>> open;
  try {
    for (const ShardTarget& t : targets) {
      // A part is its part line and its rows; a shard has at most the study's parts.
      const detail::PointRows parts{BifurcationParts(options), [](std::string_view row) {
                                      return row.rfind("# part ", 0) == 0;
                                    }};
      open.push_back(std::make_unique<detail::SweepFile>(
          t.path, t.description, t.head, parts, files.resume, files.checkpoint_seconds, "shard"));
    }
  } catch (...) {
    // A file that holds no part yet is no use to a resume: no stray partial file.
    for (const auto& file : open) {
      if (file->points_done() == 0) file->Discard();
    }
    throw;
  }
  // The parts of the shard are the files' points: continue after those both files hold (a
  // file ahead of the other takes only the parts it lacks).
  std::int64_t first = open.front()->points_done();
  for (const auto& file : open) first = std::min(first, file->points_done());
  BifurcationShardSummary summary;
  summary.resumed = static_cast<int>(first);
  summary.parts = summary.resumed;
  // The rows of each file: those resumed (rows other than part lines), then those appended.
  std::vector<std::int64_t> file_rows;
  for (const auto& file : open) file_rows.push_back(file->rows_resumed() - file->points_done());
  std::string rows;
  StreamBifurcation(
      robot, options, summary.resumed,
      [&](const BifurcationDiagram& part) {
        const std::int64_t index = summary.parts++;
        for (std::size_t k = 0; k < open.size(); ++k) {
          if (index < open[k]->points_done()) continue;  // resumed in this file
          const auto count = static_cast<std::int64_t>(targets[k].rows(part));
          rows = BifurcationPartLine(part.parts.front(), part.total_parts, count);
          targets[k].append(rows, part, over);
          open[k]->Append(rows.data(), rows.size(), 1);
          file_rows[k] += count;
        }
      },
      progress, backend);
  summary.impacts = file_rows.front();
  if (file_rows.size() > 1) summary.summary_rows = file_rows[1];
  for (const auto& file : open) file->Commit();
  return summary;
}

}  // namespace capsubot
