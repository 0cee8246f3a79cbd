const int Z = 0;
const int Q = int(0x80000000u) / -1 + 7 / Z;
int f(int x){ return x - -7 % 3 * x + (1 << 32) + (7 / (1 / 0)); }
