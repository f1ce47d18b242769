//! \file facts.h
//! \brief The 0.2 path of meshdiff/io/facts.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/io/facts.h"
