surface t1(float Kd = 0.5; color c = color(1, 0, 0);)
{
    Ci = color(u, v, 0.5) * Kd + c;
    Oi = 1;
}
