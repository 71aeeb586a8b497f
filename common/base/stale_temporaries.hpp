#pragma once
// A writer killed between writing its temporary file and renaming it (SIGKILL, a power cut) leaves
// NAME.tmpPID beside NAME (base/file_io.hpp). The next write of NAME in that folder removes every such
// file whose process is gone: a regular file (never a link or a folder), owned by this user, whose
// name is exactly NAME ".tmp" and digits, and whose PID names no live process. Nothing else is touched.
#include <string>

namespace fx {

// `folder` is an open descriptor of the folder that holds `name`; returns how many were removed.
int removeStaleTemporaries(int folder, const std::string& name);

}  // namespace fx
