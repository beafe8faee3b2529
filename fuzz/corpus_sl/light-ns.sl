light b() { illuminate (P, Ns, PI / 2) { Cl = color(Ns); } }
