// Starting a helper program (ffmpeg) with a pipe to its standard input, on Windows, macOS and Linux:
// popen/pclose on POSIX systems, _popen/_pclose on Windows, with the quoting of each system's shell.
#pragma once

#include <cstdio>
#include <string>

namespace pba::graphics {

/// The full path of an executable program found on PATH (entries split on ':' or, on Windows, ';';
/// "NAME.exe" tried there too), or an empty string when none is.
std::string findProgramOnPath(const std::string& name);

/// One argument quoted for the command interpreter that openWritePipe runs: /bin/sh's single quotes, or
/// cmd.exe's double quotes on Windows.
std::string quotedArgument(const std::string& argument);

/// Runs COMMAND through the system's shell with a binary pipe to its standard input; nullptr when it
/// cannot be started. A write to a program that has exited then fails instead of ending this process
/// (SIGPIPE is ignored on POSIX systems).
std::FILE* openWritePipe(const std::string& command);

/// Closes a pipe of openWritePipe and waits for the program: its exit code (0 on success), or -1 when
/// it did not exit normally.
int closeWritePipe(std::FILE* pipe);

}  // namespace pba::graphics
