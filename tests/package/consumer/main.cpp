// Solves a scene exactly and compares it with the answer stored in the file: exit 0 iff they agree.
#include <eccd/eccd.hpp>
#if CONSUMER_OWN_HEADERS
#include <eccd/api/solve.hpp>  // a layer's header by its installed path (<prefix>/include/eccd/api/solve.hpp)
#include "kernel/answer.hpp"   // the consumer's own, not eccd's (include/kernel/answer.hpp)
#include "api/solve.hpp"       // the consumer's own, not eccd's (include/api/solve.hpp)
#endif
#include <cstdio>
int main(int argc, char** argv) {
#if CONSUMER_OWN_HEADERS
  std::printf("beside eccd: %s, %s\n", consumer::kernel_answer(), consumer::api_solve());
#endif
  const eccd::Scene scene = eccd::read_scene(argc > 1 ? argv[1] : "cases/paper002/example.json");
  const eccd::Answer got = eccd::solve(scene).answer, want = scene.answer.value();  // exact by default
  auto same = [](const eccd::Instant& a, const eccd::Instant& b) {
    return a.certified() && b.certified() && *a.lo <= *b.hi && *b.lo <= *a.hi;
  };  // proved brackets that overlap
  bool ok = got.collides == want.collides && got.intervals.size() == want.intervals.size() &&
            got.contacts.size() == want.contacts.size();
  for (std::size_t i = 0; ok && i < got.intervals.size(); ++i)
    ok = same(got.intervals[i].first, want.intervals[i].first) &&
         same(got.intervals[i].second, want.intervals[i].second);
  for (const auto& [lo, hi] : got.intervals)
    std::printf("collision on [%s, %s]\n", lo.approx.c_str(), hi.approx.c_str());
  std::printf("%s the stored answer\n", ok ? "agrees with" : "DIFFERS from");
  return ok ? 0 : 1;
}
