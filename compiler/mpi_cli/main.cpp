// oasisc-mpi: the compiler's work spread over the ranks of an MPI job, started by mpirun.
//   quotient  the coarsest bisimulation of one large .aut model, its states spread over the
//             ranks' memory (docs/bisimulation.md, "Past one machine")
//   compile   a catalog whose contexts are dealt out to the ranks
//
// The command line follows oasisc's rules, from the same pieces: usage errors exit 2 (CLI11's
// own codes never reach the shell), no option takes an empty value, numbers pass
// common/command_line/number_options.hpp, --memory-budget (per rank) ends in "out of memory" rather
// than the OOM killer, and SIGINT, SIGTERM and SIGHUP take the unfinished output with them.

#include <csignal>
#include <cstdio>
#include <iostream>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "command_line/empty_values.hpp"
#include "command_line/memory_budget.hpp"
#include "command_line/memory_option.hpp"
#include "mpi_cli/commands.hpp"
#include "process/ending_signals.hpp"
#include "support/error_report.hpp"
#include "support/gmp_allocation.hpp"
#include "support/interrupt_cleanup.hpp"
#include "support/mapped_file.hpp"
#include "support/standard_output.hpp"

namespace {

using oasis::mpi_cli::kProgram;

// How long a rank that writes nothing outlives an ending signal: long enough for rank 0's
// handler (milliseconds), shorter than mpirun's second between its SIGTERM and its SIGKILL.
constexpr int kRankWaitBeforeDyingMs = 500;

// Every rank parses the same command line and would say the same about it: only rank 0 speaks,
// the others' std::cout and std::cerr go nowhere while this lives.
class QuietUnlessRoot {
 public:
  explicit QuietUnlessRoot(bool root) {
    if (root) return;
    out_ = std::cout.rdbuf(discarded_.rdbuf());
    err_ = std::cerr.rdbuf(discarded_.rdbuf());
  }
  QuietUnlessRoot(const QuietUnlessRoot&) = delete;
  QuietUnlessRoot& operator=(const QuietUnlessRoot&) = delete;
  ~QuietUnlessRoot() {
    if (out_ != nullptr) std::cout.rdbuf(out_);
    if (err_ != nullptr) std::cerr.rdbuf(err_);
  }

 private:
  std::ostringstream discarded_;
  std::streambuf* out_ = nullptr;
  std::streambuf* err_ = nullptr;
};

// The exit status of a command line that does not run a command (help, version, usage
// errors), or nullopt when it parsed and the budget is in force (`budget`, 0: none).
std::optional<int> parse(CLI::App& app, int argc, char** argv, bool root,
                         const std::string& memory_budget, std::uint64_t& budget) {
  const QuietUnlessRoot quiet(root);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;  // bad usage, distinct from 1 (the input has errors)
  }
  const std::optional<std::uint64_t> in_force =
      oasis::cli::apply_memory_budget_option(app, memory_budget, kProgram);
  if (!in_force) return 2;
  budget = *in_force;
  return std::nullopt;
}

sigset_t ending_signals() {
  sigset_t ending;
  sigemptyset(&ending);
  for (const int signal_number : oasis::process::kEndingSignals)
    sigaddset(&ending, signal_number);
  return ending;
}

// mpirun sends the ranks SIGKILL one second after SIGTERM: the cleanup handler must run within
// that second. A thread waiting in the kernel takes a signal only when it comes back, and the
// main thread syncing a large catalog file waits for seconds; a thread that takes the signal
// while another writes into the folder it removes is handled by the handler (it empties the
// folder until it is gone, and a writer stops at its next step). So one thread of its own
// takes the ending signals, and every other thread keeps them blocked: OpenMPI's, started in
// MPI_Init, the main thread and the workers it starts, which inherit the mask.
void block_ending_signals() {
  const sigset_t ending = ending_signals();
  ::pthread_sigmask(SIG_BLOCK, &ending, nullptr);
}

void take_ending_signals_on_own_thread() {
  std::thread([] {
    const sigset_t ending = ending_signals();
    ::pthread_sigmask(SIG_UNBLOCK, &ending, nullptr);
    for (;;)
      ::pause();
  }).detach();
}

}  // namespace

namespace {

// The program: its command line parsed, then the command run, every error of a command
// reported. main() catches what escapes the set-up.
int run(int argc, char** argv) {
  using namespace oasis;
  make_gmp_throw_on_allocation_failure();
  block_ending_signals();
  const distributed::Communicator communicator(argc, argv);
  // After MPI_Init, which installs OpenMPI's own handlers: ours must be the ones in force. Every
  // rank installs them (only rank 0 writes, but mpirun signals every rank).
  interrupt::install_cleanup_handlers();
  take_ending_signals_on_own_thread();
  if (!communicator.is_root()) {
    set_changed_size_note(" (rank " + std::to_string(communicator.rank()) + ")");
    // Rank 0 alone writes; this rank's death by a signal would make mpirun kill rank 0 before
    // its handler has removed the unfinished output.
    interrupt::set_wait_before_dying(kRankWaitBeforeDyingMs);
  }
  CLI::App app(
      "oasisc-mpi: oasisc's bisimulation and compile spread over the ranks of an MPI job\n"
      "(mpirun -np P oasisc-mpi COMMAND ...). Every rank runs the same command; rank 0 writes\n"
      "the output and the report. 'oasisc-mpi COMMAND --help' explains each.",
      std::string(kProgram));
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(kProgram) + " " + OASIS_VERSION);
  const mpi_cli::CommandRunner quotient = mpi_cli::add_quotient_command(app, communicator);
  const mpi_cli::CommandRunner compile = mpi_cli::add_compile_command(app, communicator);
  std::string memory_budget = "auto";
  cli::add_memory_budget_option(app, memory_budget);
  cli::refuse_empty_values(app);

  std::uint64_t budget = 0;
  if (const auto status = parse(app, argc, argv, communicator.is_root(), memory_budget, budget))
    return finish_standard_output(kProgram, *status);
  int status = 1;
  try {
    status = app.got_subcommand("quotient") ? quotient() : compile();
  } catch (const std::bad_alloc&) {
    // The other ranks may be waiting for this one in a collective: the job ends here.
    cli::report_out_of_memory(kProgram, budget);
    lift_memory_budget();  // MPI_Abort allocates to tell mpirun why the job ends
    communicator.abort(1);
  } catch (const std::exception& e) {
    oasis::report_error(kProgram, e.what());
    communicator.abort(1);
  }
  return finish_standard_output(kProgram, status);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (...) {
    // Only the set-up of the command line is left outside run()'s handlers: out of memory
    // before any command ran. No allocation here.
    std::fputs("oasisc-mpi: error: could not set up the command line\n", stderr);
    return 1;
  }
}
