#include "meshdiff/io.h"
int main()
{
    return 0;
}
