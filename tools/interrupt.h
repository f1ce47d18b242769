//! \file interrupt.h
//! \brief Ctrl-C: SIGINT and SIGTERM only set a flag, which the running
//! computation polls (through its Progress, meshdiff/core/progress.h) about every
//! 1/100 of a stage; it then stops, the outputs' temporary files are removed
//! and meshdiff exits with code 130 (kInterrupted).
#pragma once

namespace meshdiff::cli {

//! Installs the handlers of SIGINT and SIGTERM (main() does, once).
void install_interrupt_handlers();

//! True once SIGINT or SIGTERM arrived. Async-signal-safe, thread-safe.
bool interrupted();

//! The signal that arrived (SIGINT or SIGTERM), or 0.
int interrupt_signal();

}  // namespace meshdiff::cli
