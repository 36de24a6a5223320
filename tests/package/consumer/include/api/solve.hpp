#pragma once
// The consumer's own api/solve.hpp, on its include path: the same name as eccd's api/solve.hpp.
// eccd's installed headers include theirs as "eccd/api/solve.hpp", so neither is taken for the other.
namespace consumer {
inline const char* api_solve() { return "the consumer's own api/solve.hpp"; }
}  // namespace consumer
