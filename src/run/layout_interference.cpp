// The pipeline already measures each bore against the part, the keep-outs and the other bores
// with the exact solid-cylinder kernels (the clearance as upper bound) and places each
// violation; this report keeps those checks and tells crossing from mere closeness.

#include "mtcs/run/layout_interference.h"

#include <limits>

#include "mtcs/mold/decoder.h"

namespace mtcs::run {

LayoutInterference layout_interference(const eval::Pipeline& pipeline, const mold::Genome& genome) {
  const mold::Scene& scene = pipeline.scene();
  const mold::Layout layout = mold::decode(scene, genome);
  const eval::Evaluation e = pipeline.evaluate(layout);
  LayoutInterference r;
  r.bores = layout.bores.size();
  r.nearest = std::numeric_limits<double>::infinity();
  for (const auto& v : e.violations)
    if (v.kind == eval::ViolationKind::BoreCavity || v.kind == eval::ViolationKind::BoreKeepout ||
        v.kind == eval::ViolationKind::BoreBore) {
      r.found.push_back(v);
      r.crossing += v.distance <= 0;
      r.nearest = std::min(r.nearest, v.distance);
    }
  if (scene.spec().cavity) r.against.push_back("cavity");
  for (const auto& k : scene.spec().keep_outs) r.against.push_back(k.name);
  return r;
}

}  // namespace mtcs::run
