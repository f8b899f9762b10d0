#pragma once
// mtcs bench sms-emoa (experiments/sms-emoa).

#include <string>
#include <vector>

namespace mtcs::bench {

// algorithms: sms-emoa, nsga2, moead. CSV on stdout.
int bench_sms(const std::string& problem, const std::vector<std::string>& algorithms, int seeds, long evaluations);

}  // namespace mtcs::bench
