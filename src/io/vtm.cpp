// EG2D_FORMAT_VTM: VTK's XML multiblock form, laid out as VTK's own
// vtkXMLMultiBlockDataWriter lays it out: PATH = DIR/NAME.vtm, a
// vtkMultiBlockDataSet whose DataSet k ("block<k>") is the file
// NAME/NAME_<k>.vts (relative to the .vtm), each block's StructuredGrid as
// the vts format writes a grid (vts.cpp). ParaView and VTK's
// vtkXMLMultiBlockDataReader read it as one data set of the blocks.
// All or nothing: the block directory is made if missing (and removed again
// on failure), every file is written to its temporary first, then the blocks
// are put in place and the .vtm last; should the .vtm still fail there (a
// FIFO with no reader), the block files that were new are removed again
// (those that replaced an earlier set's stay replaced). Block files of an earlier, larger set
// in the directory are left as they are; the .vtm names only the set's own.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <sys/stat.h>

#include "base/error.hpp"
#include "io/formats.hpp"

namespace eg2d {

void write_vts(const WriteRequest &r, OutputFile &out);  // vts.cpp

namespace {

// Text for a double-quoted XML attribute.
std::string xml_attribute(const std::string &text) {
    std::string out;
    for (char ch : text) {
        switch (ch) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += ch;
        }
    }
    return out;
}

}  // namespace

void write_vtm(const BlocksRequest &r, const std::string &path) {
    if (r.grids.empty()) fail(Failure::Argument, format("%s: no blocks to write", path.c_str()));
    // DIR/NAME.vtm: the blocks go in DIR/NAME/, as VTK's writer puts them.
    const std::size_t slash = path.rfind('/');
    const std::size_t start = slash == std::string::npos ? 0 : slash + 1;
    const std::size_t dot = path.rfind('.');
    if (dot == std::string::npos || dot <= start)
        fail(Failure::Argument, format("%s: a VTK multiblock file needs an extension (NAME.vtm): its blocks go in the "
                                       "directory NAME beside it",
                                       path.c_str()));
    const std::string directory = path.substr(0, dot), name = path.substr(start, dot - start);

    OutputFile vtm(path);  // first: a path that cannot be written is refused before a directory is made
    MadeDirectories made;
    made.make(directory);
    std::vector<std::unique_ptr<OutputFile>> blocks;
    std::vector<std::string> new_files;  // removed again if the .vtm cannot be put in place
    vtm.print("<?xml version=\"1.0\"?>\n"
              "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" byte_order=\"LittleEndian\" "
              "header_type=\"UInt32\">\n"
              "  <vtkMultiBlockDataSet>\n");
    for (std::size_t k = 0; k < r.grids.size(); ++k) {
        const std::string file = format("%s_%zu.vts", name.c_str(), k), file_path = directory + "/" + file;
        struct stat st;
        if (lstat(file_path.c_str(), &st) != 0) new_files.push_back(file_path);
        blocks.push_back(std::make_unique<OutputFile>(file_path));
        write_vts(WriteRequest{*r.grids[k], r.settings, 0, nullptr}, *blocks.back());
        vtm.print("    <DataSet index=\"%zu\" name=\"%s\" file=\"%s\"/>\n", k, xml_attribute(r.name(k)).c_str(),
                  xml_attribute(name + "/" + file).c_str());
    }
    vtm.print("  </vtkMultiBlockDataSet>\n"
              "</VTKFile>\n");
    // Everything is written: now put it in place, the file that names the blocks last.
    try {
        for (auto &b : blocks) b->commit();
        vtm.commit();
    } catch (...) {
        for (const std::string &f : new_files) std::remove(f.c_str());
        throw;
    }
    made.keep();
}

}  // namespace eg2d
