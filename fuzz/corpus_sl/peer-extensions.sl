float total(float a[]) { float s = 0, i; for (i = 0; i < arraylength(a); i += 1) s += a[i]; return s; }
surface t(float k[] = {1, 2, 5}) {
  color c = P; point p = Cs;
  P += N * 0.1;
  float x[2] = {u, v};
  Ci = c + color(N) + total(k) + total(x);
  bake3d("a.ptc", "", P, N, "_c", Ci);
  color d = 0;
  texture3d("a.ptc", P, N, "_c", d);
}
