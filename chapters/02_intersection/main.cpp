#include "world.hpp"
int main() { return 0; }
