#pragma once
// The consumer's own kernel/answer.hpp, on its include path: the same name as eccd's kernel/answer.hpp.
// eccd's installed headers include theirs as "eccd/kernel/answer.hpp", so neither is taken for the other.
namespace consumer {
inline const char* kernel_answer() { return "the consumer's own kernel/answer.hpp"; }
}  // namespace consumer
