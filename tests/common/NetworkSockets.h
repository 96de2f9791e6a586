#pragma once
// Network sockets (TCP/UDP, IPv4/IPv6) a process holds: its /proc/PID/fd socket inodes looked up
// in /proc/net/{tcp,tcp6,udp,udp6}. Unix-domain sockets (the X server, D-Bus) are not network
// ports and are not counted.

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace sdfwb::testing {

// "tcp 0.0.0.0:8080 LISTEN"-like lines for every network socket of `pid` ("self" for this one).
inline std::vector<std::string> networkSockets(const std::string& pid) {
    std::set<std::string> inodes;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator("/proc/" + pid + "/fd", ec)) {
        std::string target = std::filesystem::read_symlink(entry.path(), ec).string();
        if (target.rfind("socket:[", 0) == 0) inodes.insert(target.substr(8, target.size() - 9));
    }
    std::vector<std::string> found;
    for (const char* table : {"tcp", "tcp6", "udp", "udp6"}) {
        std::ifstream in(std::string("/proc/net/") + table);
        std::string line;
        std::getline(in, line); // header
        while (std::getline(in, line)) {
            std::istringstream fields(line);
            std::string slot, local, remote, state, queues, timer, retransmits, uid, timeout, inode;
            fields >> slot >> local >> remote >> state >> queues >> timer >> retransmits >> uid >> timeout >> inode;
            if (inodes.count(inode)) found.push_back(std::string(table) + " " + local + " state " + state);
        }
    }
    return found;
}

} // namespace sdfwb::testing
