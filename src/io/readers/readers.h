// Private: meshdiff's own strict readers of OFF, OBJ and STL (PLY has its own
// in ply_reader.h). They replaced OpenMesh's readers, which loop forever or
// abort on malformed files (issue 13). Each reads the whole file, checks every
// header count against the bytes that follow before allocating from it, and
// throws IoError (unparsable, truncated, counts that do not match the body)
// or InvalidMeshError (non-finite coordinates, bad corners) naming the file
// and the line or element. Coordinates are rounded to float as OpenMesh's
// readers did, so that results on existing files stay the same.
#pragma once

#include "io/readers/read_util.h"

#include <string>

namespace meshdiff::detail {

//! OFF, COFF, NOFF, CNOFF, STOFF, STCOFF, ... (ASCII); see docs/cli.md.
Soup read_off(const std::string& path);

//! Wavefront OBJ: v and f lines (polygons); everything else is ignored, and
//! mtllib files are never opened.
Soup read_obj(const std::string& path);

//! STL, binary or ASCII; corners at the same position are merged into one
//! vertex as OpenMesh's reader merged them.
Soup read_stl(const std::string& path);

}  // namespace meshdiff::detail
