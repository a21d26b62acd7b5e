// Worker threads started once, for the threaded frame (render/parallel_frame.hpp).
// run(job) calls job(0) on the calling thread and job(1) .. job(size() - 1) on the workers, and
// returns when every call has returned. Nothing is allocated after construction: the job is
// passed as a pointer to the caller's callable, not as a std::function. The threads, the mutex
// and the condition variables live in worker_pool.cpp, so that this header (and the drawing
// headers that include it) pull in no thread header.
//
// Waking a thread blocked on a condition variable takes the kernel tens of microseconds, at the
// start and at the end of every run: a good part of a frame. So both sides first spin for a
// while (`spin`) on an atomic, yielding the core between looks (on a busy machine the thread
// waited for may need it), and only then block. Frames that follow each other closely never
// block; a kiosk idle between frames spins `spin` per frame per worker, then sleeps.
#pragma once

#include <chrono>
#include <memory>

namespace noneuclid::render {

class WorkerPool {
public:
    // threads >= 1 in all, the calling thread included: threads - 1 workers are started.
    explicit WorkerPool(int threads, std::chrono::microseconds spin = std::chrono::microseconds(200));
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    int size() const { return size_; }

    // job(i) for every thread i, job(0) on the calling thread; returns when all have returned.
    template <class F>
    void run(F& job) {
        if (size_ == 1) return job(0);
        run_on_all([](void* f, int i) { (*static_cast<F*>(f))(i); }, &job);
    }

    // While waiting for another thread's work: lets it run (on a shared or busy machine the
    // thread waited for may need this core).
    static void pause();

private:
    // Ends the workers and joins them (the destructor; a constructor that could not start them all).
    void stop();
    // Calls call(context, i) on every worker i and call(context, 0) here, then waits for them.
    void run_on_all(void (*call)(void*, int), void* context);

    struct Workers;  // worker_pool.cpp
    int size_;
    std::unique_ptr<Workers> workers_;
};

}  // namespace noneuclid::render
