#pragma once
// What a sweep's folder may hold (docs/sweeps.md, "Folders"): checked before a run, a --replot or
// a --gather reads or writes anything, so that the sweep never writes through a link planted in
// its folder, never reads a special file (a FIFO, /dev/zero) in place of a kept one, and never
// takes a user's folder for a case.
#include <string>

namespace acst::mpm {

// Refuses (InputError naming the entry and why) a folder whose `cases/`, `kept/` or `figures/`
// (and `figures/cases/`) is a link or not a folder; a `cases/` entry that is not a case folder
// with its record (a user's file, link or folder; hidden partial folders and leftovers are the
// sweep's own); a `kept/` entry that is a link or not a folder; or a kept case's entry that is not
// a plain file.
void require_sound_sweep_folder(const std::string& dir);

}  // namespace acst::mpm
