#pragma once
// How many CPU threads a command uses. LibTorch 1.13's own default is the number of physical cores its
// cpuinfo finds, which is 1 on some virtual machines (2 vCPUs here), and it lowers OpenMP to that in
// every thread that calls into ATen: without this, every stage ran on one core of two.

namespace cls {

// The CPUs this process may run on: its affinity mask (a Slurm or cgroup cpuset), at least 1.
int available_cpus();

// OMP_NUM_THREADS when it is a positive integer or a list starting with one ("4,2"; what run-tiles,
// Slurm tasks and `citylangsplat --threads N` set for their children), else available_cpus().
int default_cpu_threads();

}  // namespace cls
