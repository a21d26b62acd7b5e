// Worker threads started once, for the frame's parallel work (draw_world's threaded overload).
// run(job) calls job(0) on the calling thread and job(1) .. job(size() - 1) on the workers, and
// returns when every call has returned. Standard C++ only (std::thread, mutex, condition
// variable, atomics); nothing is allocated after construction: the job is passed as a pointer
// to the caller's callable, not as a std::function.
//
// Waking a thread blocked on a condition variable costs tens of microseconds (the kernel must
// schedule it), paid at the start and the end of every run: a good part of a 600 us frame. So
// both sides first spin for a while (`spin`, 200 us by default) on an atomic, yielding the core
// between looks (on a busy machine the thread we wait for may need it), and only then block.
// Frames that follow each other closely (a benchmark, a slow frame) never block; a kiosk idle
// between frames at 60 Hz spins 200 us per frame per worker, then sleeps.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace noneuclid::render {

class WorkerPool {
public:
    using clock = std::chrono::steady_clock;

    // threads >= 1 in all, the calling thread included: threads - 1 workers are started.
    explicit WorkerPool(int threads, std::chrono::microseconds spin = std::chrono::microseconds(200))
        : size_(threads < 1 ? 1 : threads), spin_(spin) {
        workers_.reserve(static_cast<std::size_t>(size_ - 1));
        for (int i = 1; i < size_; ++i) workers_.emplace_back([this, i] { loop(i); });
    }
    ~WorkerPool() {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            stop_.store(true, std::memory_order_relaxed);
            generation_.fetch_add(1, std::memory_order_release);
        }
        start_.notify_all();
        for (std::thread& t : workers_) t.join();
    }
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    int size() const { return size_; }

    template <class F>
    void run(F& job) {
        if (size_ == 1) return job(0);
        call_ = [](void* f, int i) { (*static_cast<F*>(f))(i); };
        context_ = &job;
        pending_.store(size_ - 1, std::memory_order_relaxed);
        {
            // Under the lock: a worker about to block checks the generation under it too.
            const std::lock_guard<std::mutex> lock(mutex_);
            generation_.fetch_add(1, std::memory_order_release);  // publishes call_, context_
        }
        start_.notify_all();
        job(0);
        if (!spin_until([this] { return pending_.load(std::memory_order_acquire) == 0; })) {
            std::unique_lock<std::mutex> lock(mutex_);
            done_.wait(lock, [this] { return pending_.load(std::memory_order_acquire) == 0; });
        }
    }

    // While waiting for another thread's work: let it run (on a shared or busy machine the
    // thread we wait for may need this core).
    static void pause() { std::this_thread::yield(); }

    // Asks for the cache line at p, which this thread will soon write, so that it is here and
    // writable by then. On x86 this is PREFETCHW: GCC emits it for __builtin_prefetch(p, 1)
    // only when told the target has it (-mprfchw), which the portable build does not say,
    // and gives PREFETCHT0, which fetches the line to be read: the write then still waits for
    // the other core to give up its copy. Every x86-64 core runs PREFETCHW (older Intel cores
    // as a no-op). Elsewhere __builtin_prefetch(p, 1) (aarch64: PRFM PSTL1KEEP).
    static void prefetch_for_write(const void* p) {
#if defined(__x86_64__) || defined(__i386__)
        asm volatile("prefetchw %0" : : "m"(*static_cast<const char*>(p)));
#else
        __builtin_prefetch(p, 1);
#endif
    }

private:
    // Looks at ready() until it holds (true) or the spin time is over (false), yielding between.
    template <class Ready>
    bool spin_until(Ready ready) const {
        if (ready()) return true;
        const clock::time_point end = clock::now() + spin_;
        for (int k = 0;; ++k) {
            if (ready()) return true;
            if ((k & 15) == 15 && clock::now() >= end) return false;
            pause();
        }
    }

    void loop(int index) {
        uint64_t seen = 0;
        for (;;) {
            auto started = [&] { return generation_.load(std::memory_order_acquire) != seen; };
            if (!spin_until(started)) {
                std::unique_lock<std::mutex> lock(mutex_);
                start_.wait(lock, started);
            }
            seen = generation_.load(std::memory_order_acquire);
            if (stop_.load(std::memory_order_relaxed)) return;
            call_(context_, index);
            if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
                // The caller may be about to block: take the lock so the notification cannot
                // fall between its last look and its wait.
                { const std::lock_guard<std::mutex> lock(mutex_); }
                done_.notify_one();
            }
        }
    }

    int size_;
    std::chrono::microseconds spin_;
    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable start_, done_;
    std::atomic<uint64_t> generation_{0};
    std::atomic<int> pending_{0};
    std::atomic<bool> stop_{false};
    void (*call_)(void*, int) = nullptr;
    void* context_ = nullptr;
};

}  // namespace noneuclid::render
