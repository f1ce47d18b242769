#include "meshdiff/colormap.h"
