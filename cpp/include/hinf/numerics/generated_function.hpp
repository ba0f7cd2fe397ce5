// Functions of a shared library compiled from C code that CasADi's code generator wrote
// (casadi.CodeGenerator; hinf_cpp.codegen.compile_casadi_functions in Python does the whole
// chain: generation, compilation with the system C compiler, a cache). A model written with
// CasADi symbols is then evaluated here with no Python involved.
//
// ABI. The generated C code calls its scalar type casadi_real and its integer type casadi_int;
// both are set when the code is generated. This loader is compiled for
//     casadi_real = double,   casadi_int = long long int (64 bits; CasADi's default),
// so generate with the options {"casadi_real": "double", "casadi_int": "long long int"}
// (compile_casadi_functions always does). A library that reports its sizes through
// hinf_casadi_int_size() and hinf_casadi_real_size() (compile_casadi_functions adds them) is
// checked against these when it is opened; for others, the sparsity patterns are checked to
// be valid compressed column storage, which a 32-bit casadi_int read as 64-bit is not.
//
// For a function `f` the generated code has (CasADi's C interface; the optional ones may be
// missing):
//     int f(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
//     casadi_int f_n_in(void), f_n_out(void);
//     const casadi_int* f_sparsity_in(casadi_int i), *f_sparsity_out(casadi_int i);
//     int f_work(casadi_int* sz_arg, casadi_int* sz_res, casadi_int* sz_iw, casadi_int* sz_w);
//     optional: f_incref, f_decref, f_checkout, f_release, f_alloc_mem (a function with memory),
//               f_name_in, f_name_out.
// A sparsity pattern is [nrow, ncol, colind[0..ncol], row[0..nnz-1]] (compressed column
// storage), or [nrow, ncol, 1] for a dense matrix.
//
// Thread safety: eval() may be called concurrently on one GeneratedFunction. Each call needs
// its own work arrays (CasADi's arg/res/iw/w, written during the call) and, for a function
// with memory, its own memory id:
//   * a function without memory (no f_alloc_mem: what CasADi generates for SX and most MX
//     functions) whose work arrays are small (kStackPointers, kStackIntegers, kStackReals)
//     gets them on the caller's stack: no lock and no data shared between threads, so calls
//     from several threads do not contend (a mutex taken twice per call of a 50 ns function
//     made two threads slower than one);
//   * otherwise a call takes a workspace (the arrays and a memory id from f_checkout) from a
//     pool guarded by a mutex, held only to take and return it; the pool grows to the number of
//     concurrent calls and then no longer allocates.
// CasADi's checkout/release and incref/decref update unguarded static counters in the
// generated code, so they run under one process-wide mutex, once per workspace (not per call).
//
// Errors: a missing file, a file that is not a shared library, a missing symbol, an invalid
// sparsity pattern or ABI, and wrong arguments are InputError; a generated function that
// returns nonzero (CasADi's failure flag, e.g. from an embedded solver) is a HinfError.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "hinf/core/types.hpp"

namespace hinf {

// The generated code's casadi_int and casadi_real, as this loader reads them (named apart
// from CasADi's, which its headers define as macros).
using CasadiInt = long long int;
using CasadiReal = double;

// Generated code to call: a shared library opened with dlopen(RTLD_NOW | RTLD_LOCAL) and closed
// with dlclose when the last owner goes (GeneratedFunction holds it by shared_ptr so that its code
// stays loaded), or the code of the built-in vehicles compiled into this library, found by a table
// of its entry points.
class GeneratedLibrary {
 public:
  // InputError when the file is missing, is not a whole ELF shared library of this machine's
  // kind (checked before dlopen, which would map a truncated file and die of SIGBUS on its
  // missing pages), when dlopen refuses it (with dlerror()'s reason), or when the library
  // reports another casadi_int or casadi_real size than this loader's.
  static std::shared_ptr<const GeneratedLibrary> open(const std::string& path);
  // Code compiled into the program: `symbols` maps each entry point's name to its address;
  // `label` stands for the path in messages.
  static std::shared_ptr<const GeneratedLibrary> compiled_in(std::string label,
                                                             std::map<std::string, void*> symbols);
  ~GeneratedLibrary();
  GeneratedLibrary(const GeneratedLibrary&) = delete;
  GeneratedLibrary& operator=(const GeneratedLibrary&) = delete;

  const std::string& path() const { return path_; }
  // The address of an exported symbol, or nullptr when there is none.
  void* symbol(const std::string& name) const;

 private:
  GeneratedLibrary(std::string path, void* handle, std::map<std::string, void*> symbols = {})
      : path_(std::move(path)), handle_(handle), symbols_(std::move(symbols)) {}
  std::string path_;
  void* handle_;                           // dlopen's, or null for compiled-in code
  std::map<std::string, void*> symbols_;  // compiled-in code's entry points
};

using GeneratedLibraryPtr = std::shared_ptr<const GeneratedLibrary>;

class GeneratedFunction {
 public:
  // Resolves the function `name` of the library, reads its inputs' and outputs' sizes and
  // sparsity patterns and its work sizes, and calls name_incref. InputError when a symbol is
  // missing or a pattern is invalid.
  GeneratedFunction(GeneratedLibraryPtr library, const std::string& name);
  // Opens the library at `path` (GeneratedLibrary::open) and resolves `name` in it.
  GeneratedFunction(const std::string& path, const std::string& name);
  ~GeneratedFunction();  // releases the pool's memories, calls name_decref
  GeneratedFunction(const GeneratedFunction&) = delete;
  GeneratedFunction& operator=(const GeneratedFunction&) = delete;

  const std::string& name() const { return name_; }
  const GeneratedLibraryPtr& library() const { return library_; }
  int n_in() const { return static_cast<int>(inputs_.size()); }
  int n_out() const { return static_cast<int>(outputs_.size()); }
  // Shapes and names (name_in/name_out, or "i0", "o0", ... when the library has none); i out of
  // range is an InputError.
  int input_rows(int i) const { return input(i).rows; }
  int input_cols(int i) const { return input(i).cols; }
  int output_rows(int i) const { return output(i).rows; }
  int output_cols(int i) const { return output(i).cols; }
  const std::string& input_name(int i) const { return input(i).name; }
  const std::string& output_name(int i) const { return output(i).name; }

  // inputs[i] points to input i as a dense column-major rows x cols array (entries outside the
  // input's sparsity pattern are not read; nullptr is an input of zeros); outputs[i] to dense
  // column-major storage for output i, written in full (zero where the output is structurally
  // zero), or nullptr when that output is not wanted. The arrays hold n_in() and n_out()
  // pointers. HinfError when the generated function returns nonzero.
  void eval(const double* const* inputs, double* const* outputs) const;
  // The same with sizes checked (InputError naming the input and the shapes); allocates the
  // outputs.
  std::vector<Mat> eval(const std::vector<Mat>& inputs) const;

  // Work arrays up to these sizes are taken on the stack (about 10 kB) when the function has
  // no memory (see Thread safety above).
  static constexpr int kStackPointers = 64;   // sz_arg, sz_res
  static constexpr int kStackIntegers = 128;  // sz_iw
  static constexpr int kStackReals = 1024;    // sz_w + the sparse inputs' and outputs' nonzeros
  // Whether calls use stack arrays (true) or the workspace pool.
  bool uses_stack() const { return uses_stack_; }
  // Whether calls hand the caller's arrays to the generated code as they are: a function on the
  // stack whose inputs and outputs are all dense and whose pointer work arrays are just its
  // inputs and outputs (what CasADi generates for SX functions with dense outputs, such as the
  // built-in vehicles'); no copy, no scatter, a few nanoseconds per call.
  bool passes_through() const { return passes_through_; }

 private:
  using EvalFn = int (*)(const CasadiReal**, CasadiReal**, CasadiInt*, CasadiReal*, int);
  using RefFn = void (*)(void);
  using CheckoutFn = int (*)(void);
  using ReleaseFn = void (*)(int);

  // One input or output: shape, name and sparsity pattern (colind, row empty when dense).
  struct Port {
    std::string name;
    int rows = 0, cols = 0, nnz = 0;
    bool dense = true;
    std::vector<CasadiInt> colind, row;
    int buffer_offset = 0;  // of its sparse values in a workspace's buffer (sparse ports only)
  };
  // What one call needs, owned by one thread at a time.
  struct Workspace {
    Workspace() = default;
    ~Workspace();  // release(mem), when checked out
    Workspace(const Workspace&) = delete;
    Workspace& operator=(const Workspace&) = delete;
    std::vector<const CasadiReal*> arg;
    std::vector<CasadiReal*> res;
    std::vector<CasadiInt> iw;
    std::vector<CasadiReal> w;
    std::vector<double> sparse_values;  // the sparse inputs' and outputs' nonzeros
    int mem = 0;                        // from name_checkout, when the library has it
    ReleaseFn release = nullptr;
  };
  // Takes a workspace from the pool for the duration of one call (returns it when destroyed).
  class WorkspaceLease;
  // The arrays of one call, from the stack or a workspace.
  struct Scratch {
    const CasadiReal** arg;
    CasadiReal** res;
    CasadiInt* iw;
    CasadiReal* w;
    double* sparse_values;
    int mem;
  };
  void eval_with(const Scratch& scratch, const double* const* inputs, double* const* outputs) const;
  [[noreturn]] void throw_failure(int status) const;

  const Port& input(int i) const;
  const Port& output(int i) const;
  Port read_port(bool is_input, CasadiInt i) const;
  void* required_symbol(const std::string& suffix) const;
  std::unique_ptr<Workspace> make_workspace() const;

  GeneratedLibraryPtr library_;
  std::string name_;
  EvalFn eval_ = nullptr;
  RefFn decref_ = nullptr;
  CheckoutFn checkout_ = nullptr;
  ReleaseFn release_ = nullptr;
  std::vector<Port> inputs_, outputs_;
  CasadiInt sz_arg_ = 0, sz_res_ = 0, sz_iw_ = 0, sz_w_ = 0;
  int sparse_values_size_ = 0;
  bool uses_stack_ = false;
  bool passes_through_ = false;
  mutable std::mutex pool_mutex_;
  mutable std::vector<std::unique_ptr<Workspace>> pool_;  // the workspaces not in use
  mutable std::size_t workspaces_made_ = 0;                // pool_'s capacity is kept at least this
};

}  // namespace hinf
