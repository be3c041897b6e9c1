#include <cstdio>
int main(int, char**) { std::puts("triptych"); return 0; }
