#include "render/worker_pool.hpp"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace noneuclid::render {

struct WorkerPool::Workers {
    using clock = std::chrono::steady_clock;

    explicit Workers(std::chrono::microseconds s) : spin(s) {}

    // Looks at ready() until it holds (true) or the spin time is over (false), yielding between.
    template <class Ready>
    bool spin_until(Ready ready) const {
        if (ready()) return true;
        const clock::time_point end = clock::now() + spin;
        for (int k = 0;; ++k) {
            if (ready()) return true;
            if ((k & 15) == 15 && clock::now() >= end) return false;
            pause();
        }
    }

    // Worker `index`: waits for each run's generation, calls the job, reports it done.
    void loop(int index) {
        uint64_t seen = 0;
        for (;;) {
            auto started = [&] { return generation.load(std::memory_order_acquire) != seen; };
            if (!spin_until(started)) {
                std::unique_lock<std::mutex> lock(mutex);
                start.wait(lock, started);
            }
            seen = generation.load(std::memory_order_acquire);
            if (stop.load(std::memory_order_relaxed)) return;
            call(context, index);
            if (pending.fetch_sub(1, std::memory_order_acq_rel) == 1) {
                // The caller may be about to block: take the lock so the notification cannot
                // fall between its last look and its wait.
                { const std::lock_guard<std::mutex> lock(mutex); }
                done.notify_one();
            }
        }
    }

    std::chrono::microseconds spin;
    std::vector<std::thread> threads;
    std::mutex mutex;
    std::condition_variable start, done;
    std::atomic<uint64_t> generation{0};
    std::atomic<int> pending{0};
    std::atomic<bool> stop{false};
    void (*call)(void*, int) = nullptr;
    void* context = nullptr;
};

WorkerPool::WorkerPool(int threads, std::chrono::microseconds spin)
    : size_(threads < 1 ? 1 : threads), workers_(std::make_unique<Workers>(spin)) {
    workers_->threads.reserve(static_cast<std::size_t>(size_ - 1));
    try {
        for (int i = 1; i < size_; ++i) workers_->threads.emplace_back([this, i] { workers_->loop(i); });
    } catch (...) {  // a thread that cannot start (std::system_error): those started end first
        stop();
        throw;
    }
}

WorkerPool::~WorkerPool() { stop(); }

void WorkerPool::stop() {
    Workers& w = *workers_;
    {
        const std::lock_guard<std::mutex> lock(w.mutex);
        w.stop.store(true, std::memory_order_relaxed);
        w.generation.fetch_add(1, std::memory_order_release);
    }
    w.start.notify_all();
    for (std::thread& t : w.threads) t.join();
}

void WorkerPool::pause() { std::this_thread::yield(); }

void WorkerPool::run_on_all(void (*call)(void*, int), void* context) {
    Workers& w = *workers_;
    w.call = call;
    w.context = context;
    w.pending.store(size_ - 1, std::memory_order_relaxed);
    {
        // Under the lock: a worker about to block checks the generation under it too.
        const std::lock_guard<std::mutex> lock(w.mutex);
        w.generation.fetch_add(1, std::memory_order_release);  // publishes call, context
    }
    w.start.notify_all();
    call(context, 0);
    if (!w.spin_until([&w] { return w.pending.load(std::memory_order_acquire) == 0; })) {
        std::unique_lock<std::mutex> lock(w.mutex);
        w.done.wait(lock, [&w] { return w.pending.load(std::memory_order_acquire) == 0; });
    }
}

}  // namespace noneuclid::render
