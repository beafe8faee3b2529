/* constant: the surface colour, unlit. */
surface constant()
{
    Oi = Os;
    Ci = Os * Cs;
}
