/* commands.h - the subcommands of the `mink` binary. Each takes the
 * arguments after its name (argv[0] is the subcommand name), prints its own
 * --help, and returns the process exit status. */
#ifndef MINK_EXP_COMMANDS_H
#define MINK_EXP_COMMANDS_H

int mkCmd_Sum(int argc, char **argv);
int mkCmd_Bench(int argc, char **argv);
int mkCmd_Scene(int argc, char **argv);
int mkCmd_Methods(int argc, char **argv);
int mkCmd_Verify(int argc, char **argv);
int mkCmd_Collide(int argc, char **argv);
/* `mink collide --pairs FILE`: the batched queries (cmd_pairs.c). */
int mkCmd_CollidePairs(int argc, char **argv);
int mkCmd_Plan(int argc, char **argv);
int mkCmd_Score(int argc, char **argv);

#endif
