//! \file io.h
//! \brief The 0.2 path of meshdiff/io/io.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/io/io.h"
