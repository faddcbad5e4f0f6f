// The demo gallery: the case files of examples/, embedded at build time
// (embed_examples.cmake writes demos_data.cpp), so `eg2d demo` needs no file.
#pragma once

#include <string>
#include <vector>

namespace eg2dtool {

struct Demo {
    const char *name;  // the example's file stem, e.g. "swan"
    const char *text;  // the whole case file
};

const std::vector<Demo> &demos();
const char *default_demo();  // "swan"

}  // namespace eg2dtool
