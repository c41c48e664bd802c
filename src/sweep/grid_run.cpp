#include "sweep/grid_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "sweep/shard_set.hpp"
#include "sweep/sweep_file.hpp"
#include "sweep/sweep_rows.hpp"

namespace capsubot::detail {
namespace {

// The message of a write error after which the partial file and its checkpoint are kept.
std::string KeptMessage(const IoError& e, const std::string& output) {
  return fmt::format("{}; the rows done are kept in {} with its checkpoint {} for a resume",
                     e.what(), SweepFile::PartialPath(output), SweepFile::CheckpointPath(output));
}

// The points of the run's rows: in robot mode (docs/model.md section 8) a point's first row
// has orbit = 1, or an empty orbit cell when the point has no orbit; else each row is a point.
PointRows GridPointRows(const GridRun& run) {
  PointRows rows;
  rows.points = run.points;
  const std::string_view header(run.header);
  const std::size_t names =
      header.rfind('\n', header.size() - std::min<std::size_t>(header.size(), 2));
  const int orbit =
      HeaderColumn(names == std::string_view::npos ? header : header.substr(names + 1), "orbit");
  if (orbit >= 0) {
    rows.starts_point = [orbit](std::string_view row) {
      const std::string_view cell = RowCell(row, orbit);
      return cell.empty() || cell == "1";
    };
  }
  return rows;
}

}  // namespace

std::int64_t ShardCount(std::int64_t total, int shard, int shards) {
  return shards <= 1 ? total : (total - shard + shards - 1) / shards;
}

std::string GridHeader(const std::vector<std::string>& comments, int shard, int shards,
                       std::int64_t total, const std::vector<std::string>& columns) {
  std::string text;
  for (const std::string& line : comments) text += "# " + line + '\n';
  if (shards > 1) text += ShardLine(shard, shards, total);
  std::string header;
  for (const std::string& name : columns) header += (header.empty() ? "" : ",") + name;
  return text + header + '\n';
}

SweepSummary RunGridRows(const GridRun& run, const BlockComputeFactory& blocks,
                         const SweepProgressCallback& progress, const BlockBackend& backend) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const std::int64_t total = run.points;
  SweepFile file(run.output, run.description, run.header, GridPointRows(run), run.resume,
                 run.checkpoint_seconds);
  SweepSummary summary;
  summary.threads = run.threads;
  summary.points_resumed = file.points_done();
  BlockPlan plan;
  plan.first = file.points_done();
  plan.end = total;
  plan.threads = run.threads;
  plan.block = run.block_points(total - plan.first, backend.Threads(run.threads));

  // Where the first error came from: a point (deterministic: a resume would fail the same
  // way), the file (a write error: a resume can continue once it is mended) or `progress`.
  enum class Origin { kPoint, kFile, kProgress } origin = Origin::kPoint;
  const BlockSink sink = [&](std::int64_t begin, std::int64_t end, const std::string& bytes,
                             std::int64_t rows) {
    try {
      file.Append(bytes.data(), bytes.size(), end - begin);
    } catch (const IoError&) {
      origin = Origin::kFile;
      throw;
    }
    summary.rows += rows;
    if (progress) {
      origin = Origin::kProgress;
      SweepProgress p;
      p.points_done = end;
      p.points_total = total;
      p.points_resumed = plan.first;
      p.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      progress(p);
      origin = Origin::kPoint;
    }
  };
  try {
    backend.Run(plan, blocks, sink);
  } catch (const IoError& e) {
    if (origin != Origin::kFile || file.direct()) throw;
    throw SweepResumableError(KeptMessage(e, run.output));
  } catch (...) {
    if (origin == Origin::kPoint) file.Discard();  // no resume could get past that point
    throw;
  }
  try {
    file.Commit();
  } catch (const IoError& e) {
    if (file.direct()) throw;
    throw SweepResumableError(KeptMessage(e, run.output));
  }
  summary.points = total;
  summary.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return summary;
}

}  // namespace capsubot::detail
