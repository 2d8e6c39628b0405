/* SPDX-License-Identifier: MIT */
/* A 5x7 bitmap font for the legend: digits, '.', '-', '+', 'e' and the
 * letters of "speed" and "psi6". Enough for the labels; no font library needed. */
#ifndef RENDER_FONT_H
#define RENDER_FONT_H

#define RF_WIDTH 5
#define RF_HEIGHT 7

/* RF_HEIGHT rows, top first; bit RF_WIDTH-1 is the leftmost pixel. An
 * unknown character is blank. */
const unsigned char *rf_glyph(char c);

#endif
