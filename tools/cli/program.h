#pragma once
// One exit-code rule for every program of ochre (docs/cli.md, "Exit codes"). Each main() hands its work to
// run_program, which turns what escapes it into the exit code and a message naming the program:
//   0  done (also -h/--help and --version);
//   1  internal error: a bug, memory exhausted while working, a helper program (a plot script) that failed
//      although the input was fine: "PROGRAM: internal error: ...";
//   2  bad input or usage: an unknown option, a bad value, a missing or unreadable file, InputError,
//      GraphError, ImageError, a file system error on a path given: "PROGRAM: error: ..." (the message names
//      the file and the option or field); nothing is written;
//   3  `ochre render` stopped at --time-limit;
//   4  a check the user asked for did not pass (ochre-diff: a threshold exceeded; ochre-regress: a scene
//      failed; ochre-brdf chi2: the sampler rejected; `ochre merge --check`: samples missing).
// A program ended by SIGINT, SIGTERM or SIGHUP ends by the signal (renderer/util/signal_cleanup.h, which
// the programs that write files install themselves): nothing here touches signals.

#include <functional>

namespace ochre {

enum ExitCode : int {
  kExitDone = 0,
  kExitInternalError = 1,
  kExitBadInput = 2,
  kExitTimeLimit = 3,
  kExitCheckFailed = 4,
};

// Runs `body` (a program's whole work, command line included) as the program `program` and returns its
// exit code: what body returns, or for an exception that escapes it the code above, after printing the
// message. Call once, from main().
int run_program(const char* program, const std::function<int()>& body);

// The program's name given to run_program ("ochre" before), for messages.
const char* program_name();

// Call inside a catch block: prints the exception being handled as run_program does and returns its exit
// code (2 for bad input, 1 otherwise).
int report_current_exception();

}  // namespace ochre
