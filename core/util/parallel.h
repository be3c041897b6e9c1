#pragma once
// Independent work items on the machine's cores: f(0) .. f(n - 1), each exactly once, on up to
// hardware_concurrency() threads; returns when all are done and rethrows the first exception
// (by item order) a call threw. For work whose items share nothing writable: each item writes
// only its own outputs (a pipeline's files, a pair's result slot).
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <future>
#include <system_error>
#include <thread>
#include <vector>

namespace tp {

template <class F> void forEachInParallel(size_t n, F&& f) {
    const size_t workers =
        std::min<size_t>(n, std::max(1u, std::thread::hardware_concurrency()));
    std::atomic<size_t> next{0};
    std::vector<std::exception_ptr> errors(n);
    auto work = [&] {
        for (size_t i = next++; i < n; i = next++) {
            try {
                f(i);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        }
    };
    std::vector<std::future<void>> running;
    try {
        for (size_t w = 1; w < workers; ++w)
            running.push_back(std::async(std::launch::async, work));
    } catch (const std::system_error&) {
        // No more threads to be had: the ones running and this one do the rest.
    }
    work();
    for (std::future<void>& r : running)
        r.get();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

} // namespace tp
