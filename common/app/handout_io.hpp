#pragma once
// What the handout builder does with files and programs: reads a report's JSON and looks into it
// without copies, runs a program with its output in a log (an error quotes the log's end), moves a
// capture into the handout and copies a picture into it (atomically, base/file_io.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/result.hpp"

namespace fx::handout {

using json = nlohmann::ordered_json;

Result<json> readJson(const std::filesystem::path& file);
// A member of a JSON object, or null: a reference into the report, never a copy of it.
const json& member(const json& object, const char* key);
// "1280x720" from a report's [1280, 720], or "?".
std::string sizeText(const json& size);

// Runs `program` with its standard output and error in `log`; a failure says `what` failed, with the
// last lines of the log (a lesson's own words about the step that failed).
Status runLogged(const std::filesystem::path& program, const std::vector<std::string>& args,
                 const std::filesystem::path& log, const std::string& what);
// The last `lines` lines of a log, for an error message.
std::string logTail(const std::filesystem::path& log, int lines = 12);
// A program on PATH ("dot"), or empty (Windows: PATH split at ";", each of PATHEXT tried: "dot.exe").
std::filesystem::path findProgram(const std::string& name);

// A file written by the app (a capture) into the handout: renamed, so it stays whole.
Status moveFile(const std::filesystem::path& from, const std::filesystem::path& to);
// A picture of the source tree or the bench into the handout, written atomically.
Status copyPicture(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace fx::handout
