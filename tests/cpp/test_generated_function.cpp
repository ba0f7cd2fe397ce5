// GeneratedFunction on CasADi generated code: the functions of tests/cpp/fixtures/casadi_functions.c
// (written by tests/cpp/fixtures/generate_casadi_functions.py, built into a shared library by
// CMake) against their closed forms, the dense <-> sparse conversion, concurrent evaluation,
// and the error paths (with tests/cpp/fixtures/handwritten_functions.c for the failures that
// generated code does not produce).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "hinf/core/errors.hpp"
#include "hinf/numerics/generated_function.hpp"
#include "tolerances.hpp"

namespace {

using hinf::GeneratedFunction;
using hinf::GeneratedLibrary;
using hinf::Mat;
using hinf_test::kRoundoff;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The libraries built by tests/cpp/CMakeLists.txt.
const std::string kCasadiLibrary = HINF_CASADI_FIXTURE;
const std::string kHandwrittenLibrary = HINF_HANDWRITTEN_FIXTURE;
const std::string kWrongAbiLibrary = HINF_WRONG_ABI_FIXTURE;

// The message of the exception E that call() throws ("" and a failure when it throws none).
template <class E, class Call>
std::string message_of(Call call) {
  try {
    call();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "no exception";
  return "";
}

Mat column(std::initializer_list<double> values) {
  Mat m(static_cast<Eigen::Index>(values.size()), 1);
  Eigen::Index i = 0;
  for (double v : values) m(i++, 0) = v;
  return m;
}

// Two evaluations of one formula: CasADi's generated C (compiled by the C compiler, which may
// contract to fused multiply-adds) and the closed form here; the same libm functions.
void expect_close(const Mat& actual, const Mat& expected, const std::string& what) {
  ASSERT_EQ(actual.rows(), expected.rows()) << what;
  ASSERT_EQ(actual.cols(), expected.cols()) << what;
  for (Eigen::Index j = 0; j < expected.cols(); ++j)
    for (Eigen::Index i = 0; i < expected.rows(); ++i)
      EXPECT_NEAR(actual(i, j), expected(i, j), kRoundoff * std::max(1.0, std::abs(expected(i, j))))
          << what << " (" << i << ", " << j << ")";
}

// ---------------------------------------------------------------- shapes and values

TEST(GeneratedFunction, ReportsShapesAndNames) {
  const GeneratedFunction trig(kCasadiLibrary, "trig");
  EXPECT_EQ(trig.name(), "trig");
  EXPECT_EQ(trig.n_in(), 2);
  EXPECT_EQ(trig.n_out(), 2);
  EXPECT_EQ(trig.input_rows(0), 2);
  EXPECT_EQ(trig.input_cols(0), 1);
  EXPECT_EQ(trig.input_rows(1), 1);
  EXPECT_EQ(trig.output_rows(0), 3);
  EXPECT_EQ(trig.output_rows(1), 1);
  EXPECT_EQ(trig.input_name(0), "v");
  EXPECT_EQ(trig.input_name(1), "s");
  EXPECT_EQ(trig.output_name(0), "a");
  EXPECT_EQ(trig.output_name(1), "b");
  const GeneratedFunction jacobian(kCasadiLibrary, "jacobian");
  EXPECT_EQ(jacobian.output_rows(0), 3);
  EXPECT_EQ(jacobian.output_cols(0), 3);
  EXPECT_THROW((void)trig.input_rows(2), hinf::InputError);
  EXPECT_THROW((void)trig.output_cols(-1), hinf::InputError);
}

TEST(GeneratedFunction, ScalarAndMultipleInputsMatchClosedForms) {
  const GeneratedFunction cubic(kCasadiLibrary, "cubic");
  const GeneratedFunction trig(kCasadiLibrary, "trig");
  for (double x : {-2.5, -1.0, 0.0, 0.3, 1.7, 40.0}) {
    expect_close(cubic.eval({column({x})})[0], column({x * x * x - 2.0 * x}), "cubic");
    const double v0 = 0.4 * x, v1 = 1.0 - x, s = 0.5 + x * x;
    const std::vector<Mat> out = trig.eval({column({v0, v1}), column({s})});
    ASSERT_EQ(out.size(), 2u);
    expect_close(out[0], column({std::sin(v0) * s, std::cos(v1) + s, std::exp(v0) * std::sqrt(s)}), "trig a");
    expect_close(out[1], column({v0 * v1}), "trig b");
  }
}

TEST(GeneratedFunction, MatrixInputIsColumnMajor) {
  const GeneratedFunction times(kCasadiLibrary, "times");
  Mat A(2, 2);
  A << 1.0, 2.0, 3.0, 4.0;
  expect_close(times.eval({A})[0], column({1.0 + 10.0 * 2.0, 3.0 + 10.0 * 4.0}), "A [1; 10]");
}

TEST(GeneratedFunction, SparseOutputsAreZeroFilledDense) {
  const GeneratedFunction pattern(kCasadiLibrary, "pattern");
  const GeneratedFunction jacobian(kCasadiLibrary, "jacobian");
  const double z[3] = {1.5, -2.0, 0.7};
  const double* inputs[1] = {z};
  // Outputs start as NaN: every entry, structural zero or not, must be written.
  double M[9], J[9];
  std::fill(M, M + 9, kNaN);
  std::fill(J, J + 9, kNaN);
  double* m_out[1] = {M};
  double* j_out[1] = {J};
  pattern.eval(inputs, m_out);
  jacobian.eval(inputs, j_out);
  Mat M_expected(3, 3), J_expected(3, 3);
  M_expected << z[0], 0.0, z[1] * z[2], 0.0, z[1] * z[1], 0.0, 0.0, 0.0, std::sin(z[2]);
  J_expected << z[1], z[0], 0.0, 0.0, 0.0, std::cos(z[2]), 2.0 * z[0], 0.0, 0.0;
  expect_close(Eigen::Map<Mat>(M, 3, 3), M_expected, "pattern");
  expect_close(Eigen::Map<Mat>(J, 3, 3), J_expected, "jacobian");
  // Structural zeros are exact zeros.
  EXPECT_EQ(M[1], 0.0);
  EXPECT_EQ(M[3], 0.0);
  EXPECT_EQ(J[2 + 3 * 1], 0.0);
}

TEST(GeneratedFunction, SparseInputReadsOnlyItsPattern) {
  const GeneratedFunction diagonal(kCasadiLibrary, "diagonal");
  Mat D(2, 2);
  D << 3.0, kNaN, kNaN, 5.0;  // off-diagonal entries are outside the input's pattern
  expect_close(diagonal.eval({D})[0], column({3.0 + 2.0 * 5.0}), "D00 + 2 D11");
}

TEST(GeneratedFunction, NullInputIsZeroAndNullOutputIsSkipped) {
  const GeneratedFunction trig(kCasadiLibrary, "trig");
  const double s = 4.0;
  const double* inputs[2] = {nullptr, &s};  // v = 0
  double a[3] = {kNaN, kNaN, kNaN};
  double* outputs[2] = {a, nullptr};
  trig.eval(inputs, outputs);
  expect_close(Eigen::Map<Mat>(a, 3, 1), column({0.0, 1.0 + s, std::sqrt(s)}), "trig(0, s)");
}

TEST(GeneratedFunction, LargeWorkArraysMatchClosedForm) {
  const GeneratedFunction square(kCasadiLibrary, "square");
  EXPECT_FALSE(square.uses_stack());  // its 3240 work reals go to the pool
  Mat X(40, 40);
  for (Eigen::Index j = 0; j < 40; ++j)
    for (Eigen::Index i = 0; i < 40; ++i) X(i, j) = std::sin(1.0 + 3.0 * i + 7.0 * j);  // in [-1, 1]
  const Mat expected = X * X + Mat(X.array().sin());
  // Sums of 40 products of size <= 1 in another order than Eigen's.
  const Mat Y = square.eval({X})[0];
  EXPECT_LE((Y - expected).cwiseAbs().maxCoeff(), 40.0 * kRoundoff);
}

// Calls from several threads at once, each checked against the same call made alone. jacobian
// and pattern run on the stack; square takes workspaces from the pool.
TEST(GeneratedFunction, ConcurrentCallsMatchSerialOnes) {
  const GeneratedFunction jacobian(kCasadiLibrary, "jacobian");
  const GeneratedFunction pattern(kCasadiLibrary, "pattern");  // sparse outputs: scatter from scratch
  const GeneratedFunction square(kCasadiLibrary, "square");
  EXPECT_TRUE(jacobian.uses_stack());
  EXPECT_TRUE(pattern.uses_stack());
  constexpr int kThreads = 6, kCalls = 1500;
  const auto input = [](int thread, int call) {
    return column({0.001 * call - thread, std::sin(1.0 * call) + thread, 0.5 * thread - 0.002 * call});
  };
  const auto big_input = [](int thread, int call) { return Mat::Constant(40, 40, 0.01 * thread - 1e-4 * call); };
  const auto evaluate = [&](int t, int c) {
    const Mat z = input(t, c);
    return std::vector<Mat>{jacobian.eval({z})[0] + pattern.eval({z})[0], square.eval({big_input(t, c)})[0]};
  };
  std::vector<std::vector<std::vector<Mat>>> concurrent(kThreads, std::vector<std::vector<Mat>>(kCalls));
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int c = 0; c < kCalls; ++c) concurrent[t][c] = evaluate(t, c);
    });
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < kThreads; ++t)
    for (int c = 0; c < kCalls; ++c) {
      const std::vector<Mat> alone = evaluate(t, c);
      // The same code on the same input: exactly equal.
      ASSERT_EQ(concurrent[t][c][0], alone[0]) << "thread " << t << ", call " << c;
      ASSERT_EQ(concurrent[t][c][1], alone[1]) << "thread " << t << ", call " << c;
    }
}

// with_memory (handwritten) has CasADi's memory interface: concurrent calls must each hold a
// memory of their own (the function fails when two share one), and every memory checked out
// and every reference taken is given back when the GeneratedFunction goes.
TEST(GeneratedFunction, FunctionWithMemoryChecksOutOnePerConcurrentCall) {
  const hinf::GeneratedLibraryPtr library = GeneratedLibrary::open(kHandwrittenLibrary);
  using CountFn = int (*)(void);
  const auto outstanding = reinterpret_cast<CountFn>(library->symbol("with_memory_outstanding"));
  const auto references = reinterpret_cast<CountFn>(library->symbol("with_memory_references"));
  ASSERT_TRUE(outstanding && references);
  {
    const GeneratedFunction f(library, "with_memory");
    EXPECT_FALSE(f.uses_stack());
    EXPECT_EQ(references(), 1);
    constexpr int kThreads = 4, kCalls = 3000;
    std::vector<int> wrong(kThreads, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
      threads.emplace_back([&, t] {
        for (int c = 0; c < kCalls; ++c) {
          const double x = t + 1e-3 * c;
          try {
            if (f.eval({column({x})})[0](0, 0) != x) ++wrong[t];
          } catch (const hinf::HinfError&) {  // returned 2: a memory used by two calls at once
            ++wrong[t];
          }
        }
      });
    for (std::thread& thread : threads) thread.join();
    for (int t = 0; t < kThreads; ++t) EXPECT_EQ(wrong[t], 0) << "thread " << t;
    EXPECT_GE(outstanding(), 1);
    EXPECT_LE(outstanding(), kThreads);  // one per workspace, at most one per concurrent call
  }
  EXPECT_EQ(outstanding(), 0);
  EXPECT_EQ(references(), 0);
}

TEST(GeneratedFunction, KeepsItsLibraryLoaded) {
  hinf::GeneratedLibraryPtr library = GeneratedLibrary::open(kCasadiLibrary);
  const GeneratedFunction cubic(library, "cubic");
  EXPECT_EQ(library.use_count(), 2);
  library.reset();  // the function's copy keeps the code mapped
  expect_close(cubic.eval({column({2.0})})[0], column({4.0}), "cubic(2)");
}

// ---------------------------------------------------------------- errors

TEST(GeneratedFunction, MissingFileIsAnInputError) {
  const std::string what = message_of<hinf::InputError>([] { (void)GeneratedFunction("/nonexistent/model.so", "f"); });
  EXPECT_NE(what.find("/nonexistent/model.so"), std::string::npos) << what;
  EXPECT_NE(what.find("does not exist"), std::string::npos) << what;
}

TEST(GeneratedFunction, FileThatIsNotALibraryIsAnInputError) {
  const std::string path = ::testing::TempDir() + "hinf_test_not_a_library.so";
  {
    std::ofstream file(path);
    for (int line = 0; line < 20; ++line) file << "this is text, not a shared library\n";
  }
  const std::string what = message_of<hinf::InputError>([&] { (void)GeneratedFunction(path, "f"); });
  EXPECT_NE(what.find("'" + path + "' is not a whole shared library for this machine: it is not an ELF file"),
            std::string::npos)
      << what;
  const std::string folder = message_of<hinf::InputError>([] { (void)GeneratedFunction(::testing::TempDir(), "f"); });
  EXPECT_NE(folder.find("is a folder"), std::string::npos) << folder;
}

// A copy of the fixture library, cut to `length` bytes or with one byte changed.
std::string damaged_copy(const std::string& name, std::size_t length, std::size_t at = 0, char value = 0) {
  std::ifstream in(kCasadiLibrary, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (at != 0) bytes[at] = value;
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << bytes.substr(0, std::min(length, bytes.size()));
  return path;
}

std::size_t fixture_size() {
  std::ifstream in(kCasadiLibrary, std::ios::binary | std::ios::ate);
  return static_cast<std::size_t>(in.tellg());
}

TEST(GeneratedFunction, CutOffLibraryIsAnInputErrorNotASignal) {
  // dlopen maps a library's segments; a cut-off file was mapped past its end and the first
  // access to the missing pages killed the process with SIGBUS. Every length below must be a
  // message instead (the whole file loads, checked last).
  const std::size_t size = fixture_size();
  ASSERT_GT(size, 4096u);
  for (const std::size_t length : {std::size_t{10}, std::size_t{100}, size / 4, size / 2, size - 4096, size - 1}) {
    const std::string path = damaged_copy("hinf_test_cut_library.so", length);
    const std::string what = message_of<hinf::InputError>([&] { (void)GeneratedLibrary::open(path); });
    SCOPED_TRACE(length);
    EXPECT_NE(what.find("is not a whole shared library for this machine"), std::string::npos) << what;
    EXPECT_NE(what.find("Compile it again here"), std::string::npos) << what;
  }
  EXPECT_NO_THROW((void)GeneratedLibrary::open(damaged_copy("hinf_test_whole_library.so", size)));
}

TEST(GeneratedFunction, LibraryOfAnotherKindIsRefusedBeforeLoading) {
  // e_machine (bytes 18-19) of another processor, e_type (bytes 16-17) of an executable.
  const std::size_t size = fixture_size();
  const std::string other = damaged_copy("hinf_test_other_machine.so", size, 18, 0x7f);
  const std::string machine = message_of<hinf::InputError>([&] { (void)GeneratedLibrary::open(other); });
  EXPECT_NE(machine.find("it is for another processor"), std::string::npos) << machine;
  const std::string executable = damaged_copy("hinf_test_executable.so", size, 16, 2 /* ET_EXEC */);
  const std::string type = message_of<hinf::InputError>([&] { (void)GeneratedLibrary::open(executable); });
  EXPECT_NE(type.find("not a shared library"), std::string::npos) << type;
}

TEST(GeneratedFunction, MissingSymbolIsAnInputError) {
  const std::string what = message_of<hinf::InputError>([] { (void)GeneratedFunction(kCasadiLibrary, "no_such_function"); });
  EXPECT_NE(what.find("has no function 'no_such_function'"), std::string::npos) << what;
  EXPECT_NE(what.find("was not generated by CasADi's code generator, or the function name is wrong"), std::string::npos)
      << what;
}

TEST(GeneratedFunction, WrongInputsAreInputErrors) {
  const GeneratedFunction trig(kCasadiLibrary, "trig");
  const std::string count = message_of<hinf::InputError>([&] { trig.eval({column({1.0, 2.0})}); });
  EXPECT_NE(count.find("'trig' takes 2 inputs, got 1"), std::string::npos) << count;
  const std::string shape = message_of<hinf::InputError>([&] { trig.eval({column({1.0, 2.0, 3.0}), column({1.0})}); });
  EXPECT_NE(shape.find("input 0 (v) of 'trig' must be 2 x 1, got 3 x 1"), std::string::npos) << shape;
}

TEST(GeneratedFunction, FailureFlagIsAHinfError) {
  const GeneratedFunction failing(kHandwrittenLibrary, "failing");
  expect_close(failing.eval({column({2.0})})[0], column({2.0}), "failing(2)");
  const std::string what = message_of<hinf::HinfError>([&] { failing.eval({column({-1.0})}); });
  EXPECT_NE(what.find("'failing'"), std::string::npos) << what;
  EXPECT_NE(what.find("returned 1"), std::string::npos) << what;
  // The workspace went back to the pool: the function still evaluates.
  expect_close(failing.eval({column({3.0})})[0], column({3.0}), "failing(3)");
}

TEST(GeneratedFunction, InvalidSparsityIsAnInputError) {
  const std::string what = message_of<hinf::InputError>([] { (void)GeneratedFunction(kHandwrittenLibrary, "bad_pattern"); });
  EXPECT_NE(what.find("output 0 (o0) of 'bad_pattern'"), std::string::npos) << what;
  EXPECT_NE(what.find("not valid compressed column storage"), std::string::npos) << what;
}

TEST(GeneratedFunction, OtherIntegerWidthIsAnInputError) {
  const std::string what = message_of<hinf::InputError>([] { (void)GeneratedLibrary::open(kWrongAbiLibrary); });
  EXPECT_NE(what.find("32-bit casadi_int"), std::string::npos) << what;
  EXPECT_NE(what.find("long long int"), std::string::npos) << what;
}

}  // namespace
