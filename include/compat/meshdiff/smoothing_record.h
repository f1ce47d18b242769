//! \file smoothing_record.h
//! \brief The 0.2 path of meshdiff/studies/smoothing_record.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/studies/smoothing_record.h"
