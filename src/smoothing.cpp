#include "meshdiff/smoothing.h"
