//! \file data.h
//! \brief The bundled test meshes (tests/data/, see its PROVENANCE.md).
#pragma once

#include <string>

namespace meshdiff::test {

//! The path of the bundled test file \p name.
inline std::string data(const std::string& name)
{
    return std::string(MESHDIFF_TEST_DATA_DIR) + "/" + name;
}

}  // namespace meshdiff::test
