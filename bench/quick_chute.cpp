#include <chrono>
#include <cstdio>
#include <cstdlib>
#include "talus/scenario/chute.h"
using namespace talus;
int quick_main(int argc, char** argv) {
  ChuteSetup s;
  s.flow = s.base = weinhart_chute_contact();
  s.length = argc > 1 ? atof(argv[1]) : 20; s.width = argc > 2 ? atof(argv[2]) : 10;
  auto t0 = std::chrono::steady_clock::now();
  auto w = build_chute(s);
  auto t1 = std::chrono::steady_clock::now();
  std::printf("built %zu particles in %.2fs, dt=%g\n", w->particles().owned, std::chrono::duration<double>(t1-t0).count(), w->settings().time_step);
  w->run(20000);
  auto t2 = std::chrono::steady_clock::now();
  int steps = 2000;
  w->run(steps);
  auto t3 = std::chrono::steady_clock::now();
  auto d = w->diagnostics();
  double us = std::chrono::duration<double>(t3-t2).count()*1e6/steps/w->particles().owned;
  std::printf("us/particle-step %.4f contacts %zu entries %zu rebuilds %llu Ekin %g\n", us, d.contacts, w->pair_entries(), (unsigned long long)w->rebuilds(), d.kinetic());
  return 0;
}
