#include "shop_member.h"

#include "mtcs/mold/decoder.h"
#include "mtcs/run/shop_layout.h"

namespace mtcs::report {

ShopMember shop_member(const run::Session& session, const opt::Genotype& x) {
  ShopMember m;
  const run::MoldProblem& problem = session.problem();
  m.genome = run::shop_layout(session.scene(), problem.genome(x));
  m.layout = mold::decode(session.scene(), m.genome);
  m.plan = run::shop_plan(m.layout);
  m.score = problem.evaluate(problem.encode(m.genome));  // optimize_run's re-scoring, step for step
  return m;
}

}  // namespace mtcs::report
