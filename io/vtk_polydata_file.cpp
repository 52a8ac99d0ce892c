#include "io/vtk_polydata_file.hpp"

#include "io/atomic_file.hpp"
#include "io/vtk_quiet.hpp"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

namespace exactvis {

bool write_polydata_file(const std::string& temp_path, vtkPolyData* poly) {
  QuietVtk quiet;  // a failure is reported by the caller, as one line
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(temp_path.c_str());
  writer->SetInputData(poly);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw binary: compact and exact (doubles as stored)
  writer->SetCompressorTypeToZLib();
  return writer->Write() == 1 && writer->GetErrorCode() == 0;
}

void write_polydata_vtp(const std::string& path, vtkPolyData* poly) {
  write_atomically(path, [&](const std::string& temp) { return write_polydata_file(temp, poly); });
}

}  // namespace exactvis
