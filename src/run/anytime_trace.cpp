#include "mtcs/run/anytime_trace.h"

#include <algorithm>
#include <limits>

#include "mtcs/io/atomic_file.h"
#include "mtcs/opt/sms_emoa.h"

namespace mtcs::run {

AnytimeTrace::AnytimeTrace(const MoldOptimizer& optimizer) : optimizer_(optimizer) {
  if (!optimizer.reference_from_first_generation()) reference_ = optimizer.scaled_reference();
}

void AnytimeTrace::add(const opt::Generation& g, const store::GenerationSummary& summary) {
  if (reference_.empty()) reference_ = scaled_reference_of(g, optimizer_.scales());
  AnytimeRow row;
  row.generation = g.index;
  row.evaluations = g.evaluations;
  row.seconds = summary.seconds;
  row.best_feasible = std::numeric_limits<double>::infinity();
  for (const auto& ind : g.population)
    if (ind.score.feasible) row.best_feasible = std::min(row.best_feasible, ind.score.value);
  row.hypervolume = optimizer_.scaled_hypervolume(opt::SmsEmoa::front(g), reference_);
  row.best_so_far = rows_.empty() ? row.best_feasible : std::min(rows_.back().best_so_far, row.best_feasible);
  row.hypervolume_so_far = rows_.empty() ? row.hypervolume : std::max(rows_.back().hypervolume_so_far, row.hypervolume);
  rows_.push_back(row);
}

AnytimeTrace stored_anytime(const MoldOptimizer& optimizer, const store::RunStore& db) {
  AnytimeTrace trace(optimizer);
  for (const auto& s : db.summaries()) trace.add(*db.generation(s.index), s);
  return trace;
}

void AnytimeTrace::write_csv(const std::string& path) const {
  io::AtomicFile csv(path);
  csv.stream() << "generation,evaluations,seconds,best_feasible,best_so_far,hypervolume,hypervolume_so_far\n";
  csv.stream().precision(10);
  for (const auto& r : rows_)
    csv.stream() << r.generation << ',' << r.evaluations << ',' << r.seconds << ',' << r.best_feasible << ','
                 << r.best_so_far << ',' << r.hypervolume << ',' << r.hypervolume_so_far << '\n';
  csv.commit();
}

}  // namespace mtcs::run
