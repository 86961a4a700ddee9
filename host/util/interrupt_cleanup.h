// SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1 and SIGUSR2 during a run: the files
// its OutputBatch staged (util/file_io.h) are removed before the process dies by the signal (the
// shell reports 128 + its number: 130, 143, 129), so an interrupted run leaves no temporary and no
// new output, and every old file as it was: the all-or-nothing rule of the batch, as for a run that
// fails.
#pragma once

namespace rc {

// Blocks those signals in the calling thread (and so in every thread it starts later) and starts
// a thread that waits for them; a signal inherited as ignored (nohup, a background job) stays
// ignored. Called once, first thing in main(), before any other thread exists. Implemented in
// util/file_io.cpp, beside the staged files it removes.
void remove_staged_outputs_on_signals();

}  // namespace rc
