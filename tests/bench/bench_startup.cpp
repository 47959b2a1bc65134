// Start-up cost of the command line: `mbscope read` of 10 registers against mbpoll's, in one run.
//
// Starts `mbscope simulate --profile conformance` (no response delay) on a free loopback port,
// then runs, interleaved and each as a child process with its output kept and checked:
//   mbscope read --target tcp://127.0.0.1:PORT --unit 1 --address 0 --quantity 10
//   mbscope-full read ... (the same command in the executable with everything: the window, the
//                          plots, the simulator, the watch service; what `mbscope` was before
//                          the split, for comparison)
//   mbpoll -m tcp -p PORT -a 1 -r 1 -c 10 -t 4 -1 127.0.0.1   (mbpoll's one-shot read of the same registers)
// each measured from fork to exit (wall time on the monotonic clock, peak resident memory from
// wait4's ru_maxrss), and prints the median and the largest of each, and the ratio of mbscope's
// medians to mbpoll's. One run of each is made first and not counted (the page cache). Figures
// are printed, never asserted; every run must exit 0 with the ten values on its output, so the
// benchmark fails when a program does not work.
//
// --baseline PATH adds another `mbscope` (an earlier build's, copied aside) to the same rounds, so
// that a change's before and after come from one run, on one machine load.
//
// Usage: bench_startup [--runs N] [--mbscope PATH] [--mbpoll PATH] [--baseline PATH]
// scripts/bench-startup.sh builds Release and runs it; docs/benchmarks.md has the figures.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

long long nowNs()
{
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

struct Run {
    bool ok = false;
    int exitCode = -1;
    double ms = 0;
    long maxRssKb = 0;
    std::string output;
};

std::string readFile(const std::string &path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Runs argv with its standard output to outPath and its errors to errPath, from fork to exit.
Run runChild(const std::vector<std::string> &args, const std::string &outPath, const std::string &errPath)
{
    std::vector<char *> argv;
    for (const std::string &a : args)
        argv.push_back(const_cast<char *>(a.c_str()));
    argv.push_back(nullptr);
    Run run;
    const long long start = nowNs();
    const pid_t pid = fork();
    if (pid == 0) {
        const int out = open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (out >= 0)
            dup2(out, 1);
        if (err >= 0)
            dup2(err, 2);
        execvp(argv[0], argv.data());
        _exit(127);
    }
    if (pid < 0)
        return run;
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) != pid)
        return run;
    run.ms = double(nowNs() - start) / 1e6;
    run.maxRssKb = usage.ru_maxrss;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.ok = WIFEXITED(status) && run.exitCode == 0;
    run.output = readFile(outPath);
    if (!run.ok)
        run.output += readFile(errPath);
    return run;
}

int freePort()
{
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (fd < 0 || bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) != 0
        || getsockname(fd, reinterpret_cast<sockaddr *>(&address), &length) != 0) {
        if (fd >= 0)
            close(fd);
        return 0;
    }
    close(fd);
    return ntohs(address.sin_port);
}

bool isExecutable(const std::string &program)
{
    if (program.find('/') != std::string::npos)
        return access(program.c_str(), X_OK) == 0;
    const char *path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (access((dir + "/" + program).c_str(), X_OK) == 0)
            return true;
    }
    return false;
}

template<typename T>
T median(std::vector<T> values)
{
    if (values.empty())
        return T();
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

struct Contender {
    std::string name;
    std::vector<std::string> args;
    std::string expected; // a line every good output holds (the tenth value's)
    std::vector<double> ms;
    std::vector<long> rssKb;
    bool failed = false;
};

} // namespace

int main(int argc, char *argv[])
{
    int runs = 20;
    std::string mbscope = MBSCOPE_EXECUTABLE;
    std::string mbpoll = "mbpoll";
    std::string baseline;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else if (a == "--mbscope" && i + 1 < argc)
            mbscope = argv[++i];
        else if (a == "--mbpoll" && i + 1 < argc)
            mbpoll = argv[++i];
        else if (a == "--baseline" && i + 1 < argc)
            baseline = argv[++i];
        else {
            std::fprintf(stderr, "usage: bench_startup [--runs N] [--mbscope PATH] [--mbpoll PATH] [--baseline PATH]\n");
            return 2;
        }
    }
    const std::string full = mbscope.substr(0, mbscope.rfind('/') + 1) + "mbscope-full";

    char dirTemplate[] = "/tmp/bench_startup.XXXXXX";
    const char *dir = mkdtemp(dirTemplate);
    if (!dir) {
        std::perror("bench_startup: mkdtemp");
        return 2;
    }
    const std::string tmp = dir;
    const int port = freePort();
    const std::string ready = tmp + "/sim.ready";
    const std::string url = "tcp://127.0.0.1:" + std::to_string(port);

    // The simulator: mbscope simulate (which `mbscope` hands to mbscope-full).
    const pid_t sim = fork();
    if (sim == 0) {
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, 1);
        dup2(null, 2);
        execl(mbscope.c_str(), mbscope.c_str(), "simulate", "--profile", "conformance", "--listen", url.c_str(),
              "--ready-file", ready.c_str(), static_cast<char *>(nullptr));
        _exit(127);
    }
    struct stat st{};
    for (int i = 0; i < 400 && stat(ready.c_str(), &st) != 0; ++i)
        usleep(50000);
    if (stat(ready.c_str(), &st) != 0) {
        std::fprintf(stderr, "bench_startup: %s simulate did not get ready on %s in 20 s\n", mbscope.c_str(), url.c_str());
        kill(sim, SIGTERM);
        waitpid(sim, nullptr, 0);
        return 1;
    }

    // The conformance profile's holding register 9 holds 9 (0-99 as the test peers').
    std::vector<Contender> contenders;
    const std::vector<std::string> readArgs = {"read", "--target", url, "--unit", "1", "--address", "0", "--quantity", "10"};
    Contender light{"mbscope read", {mbscope}, "40010", {}, {}, false};
    light.args.insert(light.args.end(), readArgs.begin(), readArgs.end());
    contenders.push_back(light);
    if (!baseline.empty()) {
        if (!isExecutable(baseline)) {
            std::fprintf(stderr, "bench_startup: --baseline %s is not an executable\n", baseline.c_str());
            kill(sim, SIGTERM);
            waitpid(sim, nullptr, 0);
            return 2;
        }
        Contender before{"baseline read (--baseline)", {baseline}, "40010", {}, {}, false};
        before.args.insert(before.args.end(), readArgs.begin(), readArgs.end());
        contenders.push_back(before);
    }
    if (isExecutable(full)) {
        Contender heavy{"mbscope-full read (one binary)", {full}, "40010", {}, {}, false};
        heavy.args.insert(heavy.args.end(), readArgs.begin(), readArgs.end());
        contenders.push_back(heavy);
    }
    const bool haveMbpoll = isExecutable(mbpoll);
    if (haveMbpoll) {
        contenders.push_back({"mbpoll -1", {mbpoll, "-m", "tcp", "-p", std::to_string(port), "-a", "1", "-r", "1", "-c", "10",
                                             "-t", "4", "-1", "127.0.0.1"},
                              "[10]:", {}, {}, false});
    } else {
        std::printf("mbpoll is not installed (Debian: mbpoll): mbscope alone is measured\n");
    }

    const std::string out = tmp + "/out.txt";
    const std::string err = tmp + "/err.txt";
    int failures = 0;
    for (int round = -1; round < runs; ++round) {
        for (Contender &c : contenders) {
            const Run run = runChild(c.args, out, err);
            if (!run.ok || run.output.find(c.expected) == std::string::npos) {
                if (!c.failed)
                    std::fprintf(stderr, "bench_startup: %s failed (exit %d):\n%s\n", c.name.c_str(), run.exitCode,
                                 run.output.c_str());
                c.failed = true;
                ++failures;
                continue;
            }
            if (round < 0)
                continue; // the warm-up run
            c.ms.push_back(run.ms);
            c.rssKb.push_back(run.maxRssKb);
        }
    }
    kill(sim, SIGTERM);
    waitpid(sim, nullptr, 0);
    std::remove(out.c_str());
    std::remove(err.c_str());
    std::remove(ready.c_str());
    rmdir(tmp.c_str());

    std::printf("start-up: 10 holding registers read from mbscope simulate (profile conformance) on %s, %d runs each, "
                "interleaved, after one uncounted run each\n\n",
                url.c_str(), runs);
    std::printf("%-32s %12s %12s %16s %16s\n", "program", "median ms", "max ms", "median peak MiB", "max peak MiB");
    for (const Contender &c : contenders) {
        std::printf("%-32s %12.1f %12.1f %16.1f %16.1f\n", c.name.c_str(), median(c.ms),
                    c.ms.empty() ? 0.0 : *std::max_element(c.ms.begin(), c.ms.end()), double(median(c.rssKb)) / 1024.0,
                    c.rssKb.empty() ? 0.0 : double(*std::max_element(c.rssKb.begin(), c.rssKb.end())) / 1024.0);
    }
    if (haveMbpoll && !contenders.front().ms.empty() && !contenders.back().ms.empty()) {
        const Contender &m = contenders.front();
        const Contender &p = contenders.back();
        std::printf("\nmbscope read / mbpoll: time %.2fx, peak memory %.2fx\n", median(m.ms) / median(p.ms),
                    double(median(m.rssKb)) / double(median(p.rssKb)));
    }
    return failures ? 1 : 0;
}
