#include "meshdiff/roughness.h"
