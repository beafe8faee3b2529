#define N 4
float f(float x; output float y) { y = x; if (x > 1) return 2; return x; }
surface c(float k[2] = {1, 2}; string s = "a";) {
    float i, y, z = 0;
    for (i = 0; i < N; i += 1) { if (u > i) { continue; } z += f(i, y); if (z > 3) break; }
    while (z > 0) z -= 1;
    illuminance (P, N, PI / 2) { Ci += Cl * (normalize(L) . normalize(N)); }
    Ci += color "hsv" (u, v, k[1]) * (s == "a" ? 1 : 0);
}
