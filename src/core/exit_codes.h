#pragma once
// The exit statuses of `citylangsplat`, one list so that scripts can rely on them (README, --help).
namespace cls {

constexpr int kExitOk = 0;
constexpr int kExitError = 1;           // bad input: a file missing, malformed or inconsistent (the message names it)
constexpr int kExitUsage = 2;           // bad command line
constexpr int kExitInternal = 3;        // a bug: please report it
constexpr int kExitMissingWeights = 4;  // `run --models clip`: CLIP/SAM weights not found; nothing trained
constexpr int kExitMisaligned = 5;      // `align-check`: fewer sparse points near the city model than --min-fraction
constexpr int kInterruptedExit = 130;   // stopped by SIGINT/SIGTERM after a checkpoint (the shell's 128 + SIGINT)

// The table printed by `--help` of the commands that use them.
inline constexpr const char* kExitCodesHelp =
    "exit status: 0 done, 1 bad input (the message names the file), 2 bad command line, 3 internal error, "
    "4 model weights missing (run --models clip), 5 misaligned (align-check --min-fraction), 130 interrupted "
    "(run the same command again to resume)";

}  // namespace cls
