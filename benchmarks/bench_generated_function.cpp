// The cost of one evaluation of a function of a CasADi generated library through
// GeneratedFunction, in a C++ loop (no Python):
//   hinf-bench-generated LIBRARY FUNCTION [--calls N] [--repeat R] [--threads T] [--ship]
// Every input is filled with values that change from call to call. Each of R timed rounds
// makes N calls (split over T threads sharing the one GeneratedFunction); the report is the
// median, min and max over the rounds of the seconds per call. With --ship, FUNCTION must be
// df/dq of the ship of docs/mathematics.md (one input q, the paper's parameters): it is
// checked against the hand-written ShipModel::dfdq, which is timed the same way.
// Output: one line per timing, "<label> <median> <min> <max>" in nanoseconds per call
// (benchmarks/bench_generated_function.py reads it), and a checksum of the outputs.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "hinf/core/errors.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/generated_function.hpp"

using namespace hinf;

namespace {

struct Stats {
  double median, min, max;
};

// Nanoseconds per call over `repeat` rounds of `calls` calls of round(first, count) split over
// `threads` threads (after one warm-up round).
Stats time_per_call(long calls, int repeat, int threads, const std::function<void(long, long)>& round) {
  const auto run = [&] {
    std::vector<std::thread> workers;
    const long share = calls / threads;
    for (int t = 1; t < threads; ++t) workers.emplace_back(round, t * share, share);
    round(0, share);
    for (std::thread& worker : workers) worker.join();
  };
  run();
  std::vector<double> ns;
  for (int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    run();
    ns.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
                 static_cast<double>(calls));
  }
  std::sort(ns.begin(), ns.end());
  return {ns[ns.size() / 2], ns.front(), ns.back()};
}

void report(const char* label, const Stats& s) { std::printf("%s %.2f %.2f %.2f\n", label, s.median, s.min, s.max); }

// The input of call k: 0.3 + 0.1 j + small changes from call to call (j: the entry).
void fill_input(long call, double* x, int size) {
  const double shift = 1e-4 * static_cast<double>(call % 997);
  for (int j = 0; j < size; ++j) x[j] = 0.3 + 0.1 * j + shift * (j % 2 == 0 ? 1.0 : -1.0);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: hinf-bench-generated LIBRARY FUNCTION [--calls N] [--repeat R] [--threads T] [--ship]\n");
    return 2;
  }
  long calls = 100000;
  int repeat = 21, threads = 1;
  bool ship = false;
  for (int i = 3; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (std::strcmp(argv[i], "--calls") == 0 && has_value) calls = std::max(1L, std::atol(argv[++i]));
    else if (std::strcmp(argv[i], "--repeat") == 0 && has_value) repeat = std::max(1, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--threads") == 0 && has_value) threads = std::max(1, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--ship") == 0) ship = true;
    else {
      std::fprintf(stderr, "unknown argument %s\n", argv[i]);
      return 2;
    }
  }
  try {
    const GeneratedFunction f(argv[1], argv[2]);
    // Per-thread input and output storage (dense, column-major).
    const auto sizes = [](int n, const std::function<int(int)>& rows, const std::function<int(int)>& cols) {
      std::vector<int> s;
      for (int i = 0; i < n; ++i) s.push_back(rows(i) * cols(i));
      return s;
    };
    const std::vector<int> in_sizes = sizes(f.n_in(), [&](int i) { return f.input_rows(i); },
                                            [&](int i) { return f.input_cols(i); });
    const std::vector<int> out_sizes = sizes(f.n_out(), [&](int i) { return f.output_rows(i); },
                                             [&](int i) { return f.output_cols(i); });
    std::vector<double> checksums(static_cast<std::size_t>(threads), 0.0);
    const long share = calls / threads;

    report("generated", time_per_call(calls, repeat, threads, [&](long first, long count) {
             std::vector<std::vector<double>> in, out;
             std::vector<const double*> in_ptr;
             std::vector<double*> out_ptr;
             for (int s : in_sizes) in.emplace_back(static_cast<std::size_t>(s));
             for (int s : out_sizes) out.emplace_back(static_cast<std::size_t>(s));
             for (auto& v : in) in_ptr.push_back(v.data());
             for (auto& v : out) out_ptr.push_back(v.data());
             double sum = 0.0;
             for (long k = first; k < first + count; ++k) {
               for (std::size_t i = 0; i < in.size(); ++i) fill_input(k, in[i].data(), in_sizes[i]);
               f.eval(in_ptr.data(), out_ptr.data());
               sum += out[0].empty() ? 0.0 : out[0][0];
             }
             checksums[static_cast<std::size_t>(first / std::max(1L, share))] += sum;
           }));

    if (ship) {
      require(f.n_in() == 1 && f.input_rows(0) == 6 && f.n_out() >= 1 && f.output_rows(0) == 6 && f.output_cols(0) == 6,
              "--ship needs df/dq of the ship: one input q (6), first output 6 x 6");
      const ShipModel model;
      // The generated Jacobian against the hand-written one, on the benchmark's states.
      double largest = 0.0;
      for (long k = 0; k < 997; ++k) {
        Vec q(6);
        fill_input(k, q.data(), 6);
        Mat generated(6, 6), handwritten(6, 6);
        std::vector<double*> out_ptr(static_cast<std::size_t>(f.n_out()), nullptr);
        out_ptr[0] = generated.data();
        const double* in_ptr[1] = {q.data()};
        f.eval(in_ptr, out_ptr.data());
        model.dfdq(0.0, q, handwritten);
        largest = std::max(largest, (generated - handwritten).cwiseAbs().maxCoeff());
      }
      std::printf("ship_max_abs_difference %.3g\n", largest);
      report("handwritten", time_per_call(calls, repeat, threads, [&](long first, long count) {
               Vec q(6);
               Mat J(6, 6);
               double sum = 0.0;
               for (long k = first; k < first + count; ++k) {
                 fill_input(k, q.data(), 6);
                 model.dfdq(0.0, q, J);
                 sum += J(0, 0);
               }
               checksums[static_cast<std::size_t>(first / std::max(1L, share))] += sum;
             }));
    }
    double checksum = 0.0;
    for (double c : checksums) checksum += c;
    std::printf("checksum %.17g\n", checksum);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hinf-bench-generated: %s\n", e.what());
    return 1;
  }
  return 0;
}
