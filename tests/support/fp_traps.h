/* The FP traps every C test program runs with (fp_traps.c), paused around
 * a run that is meant to overflow: a provoked divergence, a bad input. */
#ifndef EG2D_TEST_FP_TRAPS_H
#define EG2D_TEST_FP_TRAPS_H

/* Turns the traps off; gives what fp_traps_resume needs. */
int fp_traps_pause(void);
/* Clears the flags the paused run raised and turns the traps on again. */
void fp_traps_resume(int paused);

#endif
