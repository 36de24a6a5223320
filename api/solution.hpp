#pragma once
// Solution: everything one solve returns, typed (the answer and the
// diagnostics of the run). Defined in solution/solution.hpp, below io/, so
// that io/solution_json.hpp can write it and the certified ladder can return
// it; this is its name in the API.
#include "api/options.hpp"
#include "solution/solution.hpp"
