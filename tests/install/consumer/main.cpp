// Uses the installed library as a user would: an exact cylinder distance against its closed
// form, and one mold layout evaluated through the library's pipeline (the test compares the
// objectives with the installed `mtcs evaluate`). Usage: consumer MOLD.yaml LAYOUT.yaml
#include <cmath>
#include <cstdio>

#include "mtcs/eval/pipeline.h"
#include "mtcs/geometry/cylinder_distance.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/run/session.h"

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  using mtcs::geometry::Vec3;
  // Two parallel cylinders of radius 1 and 2 whose axes lie 10 apart: 7 between the surfaces.
  const mtcs::geometry::Cylinder a{Vec3(0, 0, 0), Vec3(0, 0, 5), 1}, b{Vec3(10, 0, 0), Vec3(10, 0, 5), 2};
  const double d = mtcs::geometry::distance(a, b).distance;
  if (std::abs(d - 7) > 1e-12) {
    std::printf("cylinder distance %.17g, expected 7\n", d);
    return 1;
  }
  const mtcs::run::Session session(argv[1]);
  const auto e = session.pipeline().evaluate(mtcs::mold::load_layout(argv[2], session.spec()));
  std::printf("feasible %d\n", int(e.feasible()));
  for (const double v : e.objectives) std::printf("%.17g\n", v);
  return 0;
}
