/* SPDX-License-Identifier: MIT */
/* A 5x7 bitmap font for the legend and the label: digits, '.', '-', '+',
 * '=' and the letters of "speed", "psi6", "radius", "frame" and "t". Enough
 * for the labels; no font library needed. */
#ifndef RENDER_FONT_H
#define RENDER_FONT_H

#define RF_WIDTH 5
#define RF_HEIGHT 7

/* RF_HEIGHT rows, top first; bit RF_WIDTH-1 is the leftmost pixel. An
 * unknown character is blank. */
const unsigned char *rf_glyph(char c);

#endif
