#include <iostream>
int main() { std::cout << "dualhex: skeleton\n"; return 0; }
