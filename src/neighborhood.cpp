#include "meshdiff/neighborhood.h"
