//! \file output_file.h
//! \brief The 0.2 path of meshdiff/io/output_file.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/io/output_file.h"
