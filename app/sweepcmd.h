/* `cablesim sweep SPEC [-o DIR] [--threads N] ...`: a study over a model's values (app/sweep.c). */
#ifndef CS_SWEEPCMD_H
#define CS_SWEEPCMD_H

/* argv[1] is "sweep". Returns the exit status: 0 done, 1 the outputs failed, 2 a bad spec or usage. */
int cs_sweep_command(int argc, char **argv);

#endif
