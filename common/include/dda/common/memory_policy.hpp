#pragma once
// How the process hands memory back to the system (a program-wide policy:
// call it first thing in main, not from library code).
//
// A forward run frees and re-allocates the same large buffers on every
// open-close iterate and step (solution vectors, the contact list). glibc
// returns blocks above its mmap threshold (128 kB to start with) to the
// system at once, and the next allocation faults the pages in again and
// zeroes them: on the 10k-block 3D benchmark that was 10 % of the step
// (3.14 -> 2.81 s on two threads with the allocator told to keep them).
namespace dda {

// Keeps freed blocks up to 32 MB in the heap for reuse, and trims the heap
// only past 1 GB of free memory at its top. No effect off glibc.
void keep_freed_memory();

}  // namespace dda
