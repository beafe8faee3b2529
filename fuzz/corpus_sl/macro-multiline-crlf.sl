#define ADD(a, b) \
    ((a) + (b))
surface t() {
  Ci = ADD(1,
     ADD(u,
 2));
}
