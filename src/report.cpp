#include "meshdiff/report.h"
