#include "meshdiff/normals.h"
