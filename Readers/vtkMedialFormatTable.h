// SPDX-License-Identifier: BSD-3-Clause
/**
 * Internal: the lookups of vtkMedialFileReader's and vtkMedialFileWriter's extension
 * tables. A table is an array of rows with an `Extension` (lower case, with its dot)
 * and a `Content`; the rest of a row (the reader or writer to make) is the caller's.
 * Header only; not installed.
 */
#ifndef vtkMedialFormatTable_h
#define vtkMedialFormatTable_h

#include "vtkMedialFileReader.h"

#include <cstddef>
#include <string>

/// The row for `fileName`'s extension and `content`, or nullptr.
template <class Row, std::size_t N>
const Row* vtkMedialFindFormat(const Row (&rows)[N], const char* fileName, int content)
{
  const std::string extension = vtkMedialFileReader::GetExtension(fileName);
  for (const Row& row : rows)
  {
    if (row.Content == content && extension == row.Extension)
    {
      return &row;
    }
  }
  return nullptr;
}

/// The extensions of `content`'s rows in table order, e.g. ".vtp .vtk .ply".
template <class Row, std::size_t N>
std::string vtkMedialFormatExtensions(const Row (&rows)[N], int content)
{
  std::string list;
  for (const Row& row : rows)
  {
    if (row.Content == content)
    {
      list += (list.empty() ? "" : " ") + std::string(row.Extension);
    }
  }
  return list;
}

#endif
