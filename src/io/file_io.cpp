// SPDX-License-Identifier: MIT
#include "file_io.h"

#include <cgogn/io/error.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#define CGOGN_IO_HAS_MMAP 1
#endif

namespace cgogn::io::detail
{

namespace
{
struct FileCloser
{
	void operator()(std::FILE* f) const
	{
		std::fclose(f);
	}
};
using File = std::unique_ptr<std::FILE, FileCloser>;
} // namespace

std::string read_file(const std::string& path)
{
	File f(std::fopen(path.c_str(), "rb"));
	if (!f)
		throw Error(path, std::string("cannot open for reading: ") + std::strerror(errno));
	std::string data;
	std::size_t size = 0;
	if (std::fseek(f.get(), 0, SEEK_END) == 0)
	{
		const long s = std::ftell(f.get());
		size = s > 0 ? std::size_t(s) : 0;
		std::fseek(f.get(), 0, SEEK_SET);
	}
	// one read of the whole file, then whatever a growing or unseekable file adds
	data.resize(size);
	data.resize(std::fread(data.data(), 1, size, f.get()));
	char buf[1 << 16];
	std::size_t n;
	while ((n = std::fread(buf, 1, sizeof(buf), f.get())) > 0)
		data.append(buf, n);
	if (std::ferror(f.get()))
		throw Error(path, "read error");
	return data;
}

void write_file(const std::string& path, const std::string& data)
{
	File f(std::fopen(path.c_str(), "wb"));
	if (!f)
		throw Error(path, std::string("cannot open for writing: ") + std::strerror(errno));
	if (std::fwrite(data.data(), 1, data.size(), f.get()) != data.size())
		throw Error(path, "write error");
	if (std::fflush(f.get()) != 0)
		throw Error(path, "write error");
}

OutputFile::OutputFile(const std::string& path) : path_(path), file_(std::fopen(path.c_str(), "wb"))
{
	if (file_ == nullptr)
		throw Error(path, std::string("cannot open for writing: ") + std::strerror(errno));
}

OutputFile::~OutputFile()
{
	if (file_ != nullptr)
		std::fclose(file_);
}

void OutputFile::write(const char* bytes, std::size_t n)
{
	if (std::fwrite(bytes, 1, n, file_) != n)
		throw Error(path_, "write error");
}

void OutputFile::close()
{
	const bool flushed = std::fflush(file_) == 0;
	const bool closed = std::fclose(file_) == 0;
	file_ = nullptr;
	if (!flushed || !closed)
		throw Error(path_, "write error");
}

InputFile::InputFile(const std::string& path)
{
#ifdef CGOGN_IO_HAS_MMAP
	const int fd = ::open(path.c_str(), O_RDONLY);
	if (fd < 0)
		throw Error(path, std::string("cannot open for reading: ") + std::strerror(errno));
	struct stat st;
	if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0)
	{
		void* p = ::mmap(nullptr, std::size_t(st.st_size), PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
		if (p != MAP_FAILED)
		{
			mapping_ = p;
			mapped_size_ = std::size_t(st.st_size);
			bytes_ = std::string_view(static_cast<const char*>(p), mapped_size_);
		}
	}
	::close(fd);
	if (mapping_ != nullptr)
		return;
#endif
	read_ = read_file(path); // an empty file, a pipe, or a system without mmap
	bytes_ = read_;
}

InputFile::~InputFile()
{
#ifdef CGOGN_IO_HAS_MMAP
	if (mapping_ != nullptr)
		::munmap(mapping_, mapped_size_);
#endif
}

} // namespace cgogn::io::detail
