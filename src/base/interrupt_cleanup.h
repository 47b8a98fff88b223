// Named temporary files removed when the program is interrupted (SIGINT,
// SIGTERM, SIGHUP), so that Ctrl-C during a write leaves no ".x.msh.stereomesh-tmp-PID-XXXXXX".
// The table is process-wide because a signal handler can reach nothing else;
// it holds only paths, in fixed slots that the handler reads without locking.
#pragma once

namespace sm::base {

/// Installs the handlers (the program's main calls this once; a library that
/// embeds the kernel may leave its host's handlers alone). Each handler removes
/// the registered files, then re-raises the signal with its default action, so
/// the exit status still says which signal ended the program.
void install_interrupt_cleanup();

/// Registers a path to remove on interruption; returns its slot, or -1 when
/// the table is full or the path too long (the file is then simply not
/// removed on a signal: the write itself still works).
int register_temporary(const char* path);
/// Forgets a slot (the file was renamed into place or removed).
void unregister_temporary(int slot);

}  // namespace sm::base
