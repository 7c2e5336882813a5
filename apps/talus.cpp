#include <cstdio>
int main() { std::puts("talus " TALUS_VERSION); return 0; }
