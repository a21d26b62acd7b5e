// Worker threads started once, for the frame's parallel work (draw_world's threaded overload).
// run(job) calls job(0) on the calling thread and job(1) .. job(size() - 1) on the workers, and
// returns when every call has returned. Standard C++ only (std::thread, mutex, condition
// variable); nothing is allocated after construction: the job is passed as a pointer to the
// caller's callable, not as a std::function.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace noneuclid::render {

class WorkerPool {
public:
    // threads >= 1 in all, the calling thread included: threads - 1 workers are started.
    explicit WorkerPool(int threads) : size_(threads < 1 ? 1 : threads) {
        workers_.reserve(static_cast<std::size_t>(size_ - 1));
        for (int i = 1; i < size_; ++i) workers_.emplace_back([this, i] { loop(i); });
    }
    ~WorkerPool() {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
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
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            call_ = [](void* f, int i) { (*static_cast<F*>(f))(i); };
            context_ = &job;
            pending_ = size_ - 1;
            ++generation_;
        }
        start_.notify_all();
        job(0);
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [this] { return pending_ == 0; });
    }

    // While waiting for another thread's work: let it run (on a shared or busy machine the
    // thread we wait for may need this core).
    static void pause() { std::this_thread::yield(); }

private:
    void loop(int index) {
        uint64_t seen = 0;
        for (;;) {
            void (*call)(void*, int);
            void* context;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                start_.wait(lock, [&] { return stop_ || generation_ != seen; });
                if (stop_) return;
                seen = generation_;
                call = call_, context = context_;
            }
            call(context, index);
            {
                const std::lock_guard<std::mutex> lock(mutex_);
                if (--pending_ == 0) done_.notify_one();
            }
        }
    }

    int size_;
    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable start_, done_;
    uint64_t generation_ = 0;
    int pending_ = 0;
    bool stop_ = false;
    void (*call_)(void*, int) = nullptr;
    void* context_ = nullptr;
};

}  // namespace noneuclid::render
