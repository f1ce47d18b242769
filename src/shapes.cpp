#include "meshdiff/shapes.h"
