float g(float x) { return x + 1; }
float f(float x) { return g(x) * 2; }
surface t() { Ci = f(u); }
