#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace prisca::sim {

/// Runs `count` independent jobs on up to `threads` worker threads (plain std::thread; sim never
/// touches Qt's event loop). Job i's result lands in slot i, so the results never depend on the
/// number of threads or on scheduling. `cancelled` is polled before each job starts; skipped
/// jobs leave a default-constructed Result and are reported by `completed`. `progress(done,
/// count)` is called after each job from the worker that finished it (it must be thread-safe).
/// The first exception thrown by a job is re-thrown here after all workers have stopped.
template <class Result>
std::vector<Result> runParallel(int count, int threads, const std::function<Result(int)>& job,
                                const std::function<bool()>& cancelled = {},
                                const std::function<void(int, int)>& progress = {},
                                std::vector<bool>* completed = nullptr) {
    std::vector<Result> results(std::max(count, 0));
    std::vector<char> done(std::max(count, 0), 0);
    std::atomic<int> next{0};
    std::atomic<int> finished{0};
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    std::mutex errorMutex;
    auto worker = [&] {
        for (;;) {
            if (failed || (cancelled && cancelled())) {
                return;
            }
            const int i = next.fetch_add(1);
            if (i >= count) {
                return;
            }
            try {
                results[i] = job(i);
                done[i] = 1;
            } catch (...) {
                std::lock_guard<std::mutex> lock(errorMutex);
                if (!error) {
                    error = std::current_exception();
                }
                failed = true;
                return;
            }
            const int n = ++finished;
            if (progress) {
                progress(n, count);
            }
        }
    };
    const int workers = std::clamp(threads, 1, std::max(count, 1));
    std::vector<std::thread> pool;
    for (int w = 1; w < workers; ++w) {
        pool.emplace_back(worker);
    }
    worker();  // the calling thread works too
    for (std::thread& t : pool) {
        t.join();
    }
    if (error) {
        std::rethrow_exception(error);
    }
    if (completed) {
        completed->assign(done.begin(), done.end());
    }
    return results;
}

}  // namespace prisca::sim
