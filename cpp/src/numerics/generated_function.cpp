#include "hinf/numerics/generated_function.hpp"

#include <dlfcn.h>
#include <elf.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <utility>

#include "hinf/core/errors.hpp"

namespace hinf {

namespace {

// The largest number of entries of one input or output (rows x cols), so that indices stay
// ints. A 32-bit casadi_int read as 64-bit gives rows = nrow + 2^32 ncol, far beyond it.
constexpr CasadiInt kMaxEntries = std::numeric_limits<int>::max();
// The largest number of inputs or outputs, and of CasADi's pointer work arrays.
constexpr CasadiInt kMaxPorts = 100000;

// CasADi's generated checkout/release and incref/decref update static counters without a lock
// (the generated code is not thread-safe there), so every call of them goes through this one
// mutex, shared by all libraries (two handles of one file share their statics).
std::mutex& generated_code_mutex() {
  static std::mutex mutex;
  return mutex;
}

// dlsym's object pointer as a pointer to function (POSIX guarantees the conversion).
template <class Fn>
Fn as_function(void* symbol) {
  return reinterpret_cast<Fn>(symbol);
}

std::string last_dl_error() {
  const char* message = dlerror();
  return message ? message : "no reason given";
}

// ELF types of this machine's word size, and its machine number (0: not checked).
#if UINTPTR_MAX == 0xffffffffffffffffu
using ElfHeader = Elf64_Ehdr;
using ElfProgramHeader = Elf64_Phdr;
constexpr unsigned char kElfClass = ELFCLASS64;
#else
using ElfHeader = Elf32_Ehdr;
using ElfProgramHeader = Elf32_Phdr;
constexpr unsigned char kElfClass = ELFCLASS32;
#endif
#if defined(__x86_64__)
constexpr std::uint16_t kElfMachine = EM_X86_64;
#elif defined(__aarch64__)
constexpr std::uint16_t kElfMachine = EM_AARCH64;
#elif defined(__i386__)
constexpr std::uint16_t kElfMachine = EM_386;
#elif defined(__arm__)
constexpr std::uint16_t kElfMachine = EM_ARM;
#else
constexpr std::uint16_t kElfMachine = 0;
#endif
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
constexpr unsigned char kElfData = ELFDATA2LSB;
#else
constexpr unsigned char kElfData = ELFDATA2MSB;
#endif

// Why the file at path is not a whole shared library of this machine's kind, or "" when it is.
// dlopen maps the file's segments: a truncated library would be mapped past its end and the
// first access to the missing pages is a SIGBUS, so every segment and table must lie inside it.
std::string elf_problem(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return "it cannot be opened";
  file.seekg(0, std::ios::end);
  const std::uint64_t size = static_cast<std::uint64_t>(file.tellg());
  file.seekg(0);
  ElfHeader header{};
  if (size < sizeof header || !file.read(reinterpret_cast<char*>(&header), sizeof header))
    return str_cat("it has ", size, " bytes, fewer than an ELF header");
  if (header.e_ident[EI_MAG0] != ELFMAG0 || header.e_ident[EI_MAG1] != ELFMAG1 ||
      header.e_ident[EI_MAG2] != ELFMAG2 || header.e_ident[EI_MAG3] != ELFMAG3)
    return "it is not an ELF file";
  if (header.e_ident[EI_CLASS] != kElfClass || header.e_ident[EI_DATA] != kElfData)
    return "it is an ELF file for another word size or byte order";
  if (kElfMachine != 0 && header.e_machine != kElfMachine)
    return str_cat("it is for another processor (ELF machine ", header.e_machine, ", this one is ", kElfMachine, ")");
  if (header.e_type != ET_DYN) return "it is an ELF file but not a shared library";
  const auto inside = [size](std::uint64_t offset, std::uint64_t length) {
    return offset <= size && length <= size - offset;
  };
  if (header.e_phentsize != sizeof(ElfProgramHeader) ||
      !inside(header.e_phoff, std::uint64_t{header.e_phnum} * header.e_phentsize))
    return "its program headers are damaged or cut off";
  if (header.e_shoff != 0 && !inside(header.e_shoff, std::uint64_t{header.e_shnum} * header.e_shentsize))
    return str_cat("it is cut off (", size, " bytes; its section table ends at byte ",
                   header.e_shoff + std::uint64_t{header.e_shnum} * header.e_shentsize, ")");
  file.seekg(static_cast<std::streamoff>(header.e_phoff));
  for (int i = 0; i < header.e_phnum; ++i) {
    ElfProgramHeader segment{};
    if (!file.read(reinterpret_cast<char*>(&segment), sizeof segment)) return "its program headers cannot be read";
    if (segment.p_type == PT_LOAD && !inside(segment.p_offset, segment.p_filesz))
      return str_cat("it is cut off (", size, " bytes; a segment ends at byte ", segment.p_offset + segment.p_filesz,
                     ")");
  }
  return "";
}

}  // namespace

// ---------------------------------------------------------------- GeneratedLibrary

std::shared_ptr<const GeneratedLibrary> GeneratedLibrary::open(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status))
    throw InputError(str_cat("no shared library at '", path,
                             "': the file does not exist (compile the CasADi functions with "
                             "hinf_cpp.codegen.compile_casadi_functions, or check the path)"));
  if (fs::is_directory(status))
    throw InputError(str_cat("'", path, "' is a folder, not a shared library"));
  const std::string problem = elf_problem(path);
  if (!problem.empty())
    throw InputError(str_cat("'", path, "' is not a whole shared library for this machine: ", problem,
                             ". Compile it again here (hinf_cpp.codegen.compile_casadi_functions, or export the "
                             "SymbolicModel again)"));
  // A name without a slash would be searched for on the library path instead of taken as a file.
  const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  dlerror();  // clears an earlier error
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle)
    throw InputError(str_cat("cannot load '", path, "' as a shared library: ", last_dl_error(),
                             ". It must be a shared library for this machine compiled from CasADi's "
                             "generated C code (hinf_cpp.codegen.compile_casadi_functions makes one)"));
  std::shared_ptr<const GeneratedLibrary> library(new GeneratedLibrary(path, handle));

  // The sizes the library reports, when it does (compile_casadi_functions adds these functions).
  using SizeFn = int (*)(void);
  const auto int_size = as_function<SizeFn>(library->symbol("hinf_casadi_int_size"));
  const auto real_size = as_function<SizeFn>(library->symbol("hinf_casadi_real_size"));
  if (int_size && int_size() != static_cast<int>(sizeof(CasadiInt)))
    throw InputError(str_cat("'", path, "' was generated with a ", 8 * int_size(), "-bit casadi_int; hinf_cpp reads ",
                             8 * sizeof(CasadiInt), "-bit (generate with the option casadi_int = \"long long int\")"));
  if (real_size && real_size() != static_cast<int>(sizeof(CasadiReal)))
    throw InputError(str_cat("'", path, "' was generated with a ", 8 * real_size(),
                             "-bit casadi_real; hinf_cpp reads double (generate with casadi_real = \"double\")"));
  return library;
}

std::shared_ptr<const GeneratedLibrary> GeneratedLibrary::compiled_in(std::string label,
                                                                      std::map<std::string, void*> symbols) {
  return std::shared_ptr<const GeneratedLibrary>(new GeneratedLibrary(std::move(label), nullptr, std::move(symbols)));
}

GeneratedLibrary::~GeneratedLibrary() {
  if (handle_) dlclose(handle_);
}

void* GeneratedLibrary::symbol(const std::string& name) const {
  if (!handle_) {
    const auto found = symbols_.find(name);
    return found == symbols_.end() ? nullptr : found->second;
  }
  return dlsym(handle_, name.c_str());
}

// ---------------------------------------------------------------- the workspace pool

class GeneratedFunction::WorkspaceLease {
 public:
  explicit WorkspaceLease(const GeneratedFunction& function) : function_(function) {
    {
      std::lock_guard<std::mutex> lock(function_.pool_mutex_);
      if (!function_.pool_.empty()) {
        workspace_ = std::move(function_.pool_.back());
        function_.pool_.pop_back();
        return;
      }
    }
    // None free: one more for the pool, which makes room for it now so that returning it (in
    // the destructor) cannot fail.
    std::unique_ptr<Workspace> made = function_.make_workspace();
    std::lock_guard<std::mutex> lock(function_.pool_mutex_);
    function_.pool_.reserve(function_.workspaces_made_ + 1);
    ++function_.workspaces_made_;
    workspace_ = std::move(made);
  }
  ~WorkspaceLease() {
    std::lock_guard<std::mutex> lock(function_.pool_mutex_);
    function_.pool_.push_back(std::move(workspace_));
  }
  WorkspaceLease(const WorkspaceLease&) = delete;
  WorkspaceLease& operator=(const WorkspaceLease&) = delete;

  Workspace& operator*() const { return *workspace_; }

 private:
  const GeneratedFunction& function_;
  std::unique_ptr<Workspace> workspace_;
};

GeneratedFunction::Workspace::~Workspace() {
  if (release) {
    std::lock_guard<std::mutex> lock(generated_code_mutex());
    release(mem);
  }
}

std::unique_ptr<GeneratedFunction::Workspace> GeneratedFunction::make_workspace() const {
  auto workspace = std::make_unique<Workspace>();
  workspace->arg.assign(static_cast<std::size_t>(sz_arg_), nullptr);
  workspace->res.assign(static_cast<std::size_t>(sz_res_), nullptr);
  workspace->iw.assign(static_cast<std::size_t>(sz_iw_), 0);
  workspace->w.assign(static_cast<std::size_t>(sz_w_), 0.0);
  workspace->sparse_values.assign(static_cast<std::size_t>(sparse_values_size_), 0.0);
  if (checkout_) {
    std::lock_guard<std::mutex> lock(generated_code_mutex());
    const int mem = checkout_();
    // CasADi's checkout returns -1 when it cannot allocate or initialize another memory.
    if (mem < 0)
      throw HinfError(str_cat("'", name_, "' in '", library_->path(), "' could not check out a memory (", name_,
                              "_checkout returned ", mem, "): too many concurrent evaluations for the "
                              "generated code, or its memory failed to initialize"));
    workspace->mem = mem;
    workspace->release = release_;
  }
  return workspace;
}

// ---------------------------------------------------------------- GeneratedFunction

void* GeneratedFunction::required_symbol(const std::string& suffix) const {
  const std::string symbol_name = name_ + suffix;
  void* symbol = library_->symbol(symbol_name);
  if (!symbol)
    throw InputError(str_cat("'", library_->path(), "' has no function '", name_, "' (the symbol ", symbol_name,
                             " is missing): the library was not generated by CasADi's code generator, or the "
                             "function name is wrong (it is the name given to casadi.Function)"));
  return symbol;
}

GeneratedFunction::Port GeneratedFunction::read_port(bool is_input, CasadiInt i) const {
  using SparsityFn = const CasadiInt* (*)(CasadiInt);
  using NameFn = const char* (*)(CasadiInt);
  const char* kind = is_input ? "input" : "output";
  const auto sparsity = as_function<SparsityFn>(required_symbol(is_input ? "_sparsity_in" : "_sparsity_out"));
  const auto name_of = as_function<NameFn>(library_->symbol(name_ + (is_input ? "_name_in" : "_name_out")));

  Port port;
  const char* given_name = name_of ? name_of(i) : nullptr;
  port.name = given_name ? given_name : str_cat(is_input ? "i" : "o", i);
  const std::string subject = str_cat("the sparsity pattern of ", kind, " ", i, " (", port.name, ") of '", name_,
                                      "' in '", library_->path(), "'");
  const auto invalid = [&](const std::string& reason) {
    return InputError(str_cat(subject, " is not valid compressed column storage (", reason,
                              "): the code was generated with another casadi_int than long long int "
                              "(hinf/numerics/generated_function.hpp), or is not CasADi generated code"));
  };

  const CasadiInt* sp = sparsity(i);
  if (!sp) throw invalid("there is none");
  const CasadiInt nrow = sp[0], ncol = sp[1];
  if (nrow < 0 || ncol < 0 || nrow > kMaxEntries || ncol > kMaxEntries || (ncol > 0 && nrow > kMaxEntries / ncol))
    throw invalid(str_cat("size ", nrow, " x ", ncol));
  port.rows = static_cast<int>(nrow);
  port.cols = static_cast<int>(ncol);
  // [nrow, ncol, 1]: dense (a column index array would start with 0).
  if (sp[2] == 1) {
    port.nnz = port.rows * port.cols;
    return port;
  }
  const CasadiInt* colind = sp + 2;
  if (colind[0] != 0) throw invalid(str_cat("colind[0] = ", colind[0]));
  for (CasadiInt c = 0; c < ncol; ++c)
    if (colind[c + 1] < colind[c] || colind[c + 1] > colind[c] + nrow)
      throw invalid(str_cat("colind[", c + 1, "] = ", colind[c + 1], " after ", colind[c], " with ", nrow, " rows"));
  const CasadiInt nnz = colind[ncol];
  const CasadiInt* row = colind + ncol + 1;
  for (CasadiInt c = 0; c < ncol; ++c)
    for (CasadiInt k = colind[c]; k < colind[c + 1]; ++k)
      if (row[k] < 0 || row[k] >= nrow || (k > colind[c] && row[k] <= row[k - 1]))
        throw invalid(str_cat("row index ", row[k], " in column ", c));
  port.nnz = static_cast<int>(nnz);
  // All entries present: the values are in dense column-major order already.
  if (nnz == nrow * ncol) return port;
  port.dense = false;
  port.colind.assign(colind, colind + ncol + 1);
  port.row.assign(row, row + nnz);
  return port;
}

GeneratedFunction::GeneratedFunction(GeneratedLibraryPtr library, const std::string& name)
    : library_(std::move(library)), name_(name) {
  require(library_ != nullptr, "GeneratedFunction '", name, "': the library is null");
  using CountFn = CasadiInt (*)(void);
  using WorkFn = int (*)(CasadiInt*, CasadiInt*, CasadiInt*, CasadiInt*);
  eval_ = as_function<EvalFn>(required_symbol(""));
  const auto n_in = as_function<CountFn>(required_symbol("_n_in"))();
  const auto n_out = as_function<CountFn>(required_symbol("_n_out"))();
  const auto work = as_function<WorkFn>(required_symbol("_work"));
  require(n_in >= 0 && n_in <= kMaxPorts && n_out >= 0 && n_out <= kMaxPorts, "'", name_, "' in '",
          library_->path(), "' reports ", n_in, " inputs and ", n_out,
          " outputs: not CasADi generated code with casadi_int = long long int");
  for (CasadiInt i = 0; i < n_in; ++i) inputs_.push_back(read_port(true, i));
  for (CasadiInt i = 0; i < n_out; ++i) outputs_.push_back(read_port(false, i));
  for (std::vector<Port>* ports : {&inputs_, &outputs_})
    for (Port& port : *ports)
      if (!port.dense) {
        port.buffer_offset = sparse_values_size_;
        sparse_values_size_ += port.nnz;
      }

  const int work_status = work(&sz_arg_, &sz_res_, &sz_iw_, &sz_w_);
  require(work_status == 0 && sz_arg_ >= n_in && sz_arg_ <= kMaxPorts && sz_res_ >= n_out && sz_res_ <= kMaxPorts &&
              sz_iw_ >= 0 && sz_iw_ <= kMaxEntries && sz_w_ >= 0 && sz_w_ <= kMaxEntries,
          "'", name_, "' in '", library_->path(), "' reports invalid work sizes (", name_, "_work returned ",
          work_status, ": arg ", sz_arg_, ", res ", sz_res_, ", iw ", sz_iw_, ", w ", sz_w_, ")");

  // Optional parts of CasADi's interface. CasADi generates name_alloc_mem only for a function
  // with memory; without it, checkout returns 0 and the memory id is not used.
  const bool has_memory = library_->symbol(name_ + "_alloc_mem") != nullptr;
  checkout_ = as_function<CheckoutFn>(library_->symbol(name_ + "_checkout"));
  release_ = as_function<ReleaseFn>(library_->symbol(name_ + "_release"));
  if (!checkout_ || !release_) checkout_ = nullptr, release_ = nullptr;
  uses_stack_ = !has_memory && sz_arg_ <= kStackPointers && sz_res_ <= kStackPointers && sz_iw_ <= kStackIntegers &&
                sz_w_ + sparse_values_size_ <= kStackReals;
  passes_through_ = uses_stack_ && sparse_values_size_ == 0 && sz_arg_ == n_in && sz_res_ == n_out;
  decref_ = as_function<RefFn>(library_->symbol(name_ + "_decref"));
  if (const auto incref = as_function<RefFn>(library_->symbol(name_ + "_incref"))) {
    std::lock_guard<std::mutex> lock(generated_code_mutex());
    incref();
  } else {
    decref_ = nullptr;  // decref only what was incref'd
  }
}

GeneratedFunction::GeneratedFunction(const std::string& path, const std::string& name)
    : GeneratedFunction(GeneratedLibrary::open(path), name) {}

GeneratedFunction::~GeneratedFunction() {
  pool_.clear();  // releases the memories before decref
  if (decref_) {
    std::lock_guard<std::mutex> lock(generated_code_mutex());
    decref_();
  }
}

const GeneratedFunction::Port& GeneratedFunction::input(int i) const {
  require(i >= 0 && i < n_in(), "input index ", i, " out of range: '", name_, "' has ", n_in(), " inputs");
  return inputs_[static_cast<std::size_t>(i)];
}

const GeneratedFunction::Port& GeneratedFunction::output(int i) const {
  require(i >= 0 && i < n_out(), "output index ", i, " out of range: '", name_, "' has ", n_out(), " outputs");
  return outputs_[static_cast<std::size_t>(i)];
}

void GeneratedFunction::eval(const double* const* inputs, double* const* outputs) const {
  if (passes_through_) {
    // The generated code only reads arg[0..n_in) and res[0..n_out) (sz_arg = n_in, sz_res =
    // n_out): the caller's arrays serve as they are.
    CasadiInt iw[kStackIntegers];
    CasadiReal w[kStackReals];
    const int status = eval_(const_cast<const CasadiReal**>(inputs), const_cast<CasadiReal**>(outputs), iw, w, 0);
    if (status != 0) throw_failure(status);
    return;
  }
  if (uses_stack_) {
    const CasadiReal* arg[kStackPointers];
    CasadiReal* res[kStackPointers];
    CasadiInt iw[kStackIntegers];
    CasadiReal w[kStackReals];
    // The sparse values follow CasADi's w (their sum is at most kStackReals).
    eval_with(Scratch{arg, res, iw, w, w + sz_w_, 0}, inputs, outputs);
    return;
  }
  WorkspaceLease lease(*this);
  Workspace& ws = *lease;
  eval_with(Scratch{ws.arg.data(), ws.res.data(), ws.iw.data(), ws.w.data(), ws.sparse_values.data(), ws.mem}, inputs,
            outputs);
}

void GeneratedFunction::eval_with(const Scratch& scratch, const double* const* inputs, double* const* outputs) const {
  // Dense ports and absent arrays (nullptr: CasADi's zeros / not wanted) are passed as they are;
  // sparse inputs are gathered into, and sparse outputs written to, the scratch's sparse values.
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    const Port& port = inputs_[i];
    if (port.dense || !inputs[i]) {
      scratch.arg[i] = inputs[i];
      continue;
    }
    double* values = scratch.sparse_values + port.buffer_offset;
    for (int c = 0; c < port.cols; ++c)
      for (CasadiInt k = port.colind[c]; k < port.colind[c + 1]; ++k)
        values[k] = inputs[i][port.row[k] + static_cast<CasadiInt>(c) * port.rows];
    scratch.arg[i] = values;
  }
  for (std::size_t o = 0; o < outputs_.size(); ++o) {
    const Port& port = outputs_[o];
    scratch.res[o] = port.dense || !outputs[o] ? outputs[o] : scratch.sparse_values + port.buffer_offset;
  }
  const int status = eval_(scratch.arg, scratch.res, scratch.iw, scratch.w, scratch.mem);
  if (status != 0) throw_failure(status);
  for (std::size_t o = 0; o < outputs_.size(); ++o) {
    const Port& port = outputs_[o];
    if (port.dense || !outputs[o]) continue;
    double* dense = outputs[o];
    const double* values = scratch.sparse_values + port.buffer_offset;
    std::fill(dense, dense + static_cast<std::size_t>(port.rows) * static_cast<std::size_t>(port.cols), 0.0);
    for (int c = 0; c < port.cols; ++c)
      for (CasadiInt k = port.colind[c]; k < port.colind[c + 1]; ++k)
        dense[port.row[k] + static_cast<CasadiInt>(c) * port.rows] = values[k];
  }
}

void GeneratedFunction::throw_failure(int status) const {
  throw HinfError(str_cat("the generated function '", name_, "' in '", library_->path(), "' returned ", status,
                          " (CasADi's failure flag: an evaluation failed, e.g. an embedded solver)"));
}

std::vector<Mat> GeneratedFunction::eval(const std::vector<Mat>& inputs) const {
  require(inputs.size() == inputs_.size(), "'", name_, "' takes ", n_in(), " inputs, got ", inputs.size());
  std::vector<const double*> input_data(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const Port& port = inputs_[i];
    require(inputs[i].rows() == port.rows && inputs[i].cols() == port.cols, "input ", i, " (", port.name, ") of '",
            name_, "' must be ", port.rows, " x ", port.cols, ", got ", inputs[i].rows(), " x ", inputs[i].cols());
    input_data[i] = inputs[i].data();
  }
  std::vector<Mat> outputs;
  std::vector<double*> output_data;
  outputs.reserve(outputs_.size());
  for (const Port& port : outputs_) {
    outputs.emplace_back(port.rows, port.cols);
    output_data.push_back(outputs.back().data());
  }
  eval(input_data.data(), output_data.data());
  return outputs;
}

}  // namespace hinf
