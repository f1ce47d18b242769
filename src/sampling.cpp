#include "meshdiff/sampling.h"
