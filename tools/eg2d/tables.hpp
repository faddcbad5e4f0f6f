// The library's tables as Markdown (eg2d --tables): what docs/tables.md is
// generated from, and what a user reads to write a case file.
#pragma once
#include <string>

namespace eg2dtool {

std::string tables_markdown();

}  // namespace eg2dtool
