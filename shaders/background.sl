/* background: fills what the scene leaves uncovered with a colour. The colour is "background"
 * (RISpec's name) or "bgcolor" (Aqsis's spelling, which scenes written for it use); bgcolor,
 * when given, wins. Its default, -1, is no colour: it means "not given". */
imager background(color background = 1; color bgcolor = -1)
{
    color fill = comp(bgcolor, 0) >= 0 ? bgcolor : background;
    Ci += (1 - alpha) * fill;
    Oi = 1;
    alpha = 1;
}
