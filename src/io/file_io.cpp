// SPDX-License-Identifier: MIT
#include "file_io.h"

#include <cgogn/io/error.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

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

} // namespace cgogn::io::detail
