void f(output float x) { x = 1; }
surface t() {
  f("a");
}
