#include "meshdiff/normalize.h"
