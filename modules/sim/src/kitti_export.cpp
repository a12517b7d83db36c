#include <vlo/core/atomic_file.h>
#include <vlo/core/error.h>
#include <vlo/io/kitti_files.h>
#include <vlo/sim/kitti_export.h>

#include <cstdio>
#include <filesystem>

namespace vlo::sim
{
namespace fs = std::filesystem;
namespace
{
const char* kMarker = "vlo-sim.txt";

std::string seqDir(const std::string& root) { return root + "/sequences/00"; }

void writeMatrixLine(std::ostream& out, const char* key, const Eigen::Matrix<double, 3, 4>& M)
{
	out << key << ":";
	char buf[32];
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 4; ++c)
		{
			std::snprintf(buf, sizeof(buf), " %.12e", M(r, c));
			out << buf;
		}
	out << "\n";
}
}  // namespace

Eigen::Isometry3d KittiExporter::cam0TVelo(const SensorRig& rig) { return rig.vehicle_T_camera.inverse() * rig.vehicle_T_lidar; }

KittiExporter::KittiExporter(std::string dir, const SensorRig& rig, const std::string& description)
	: dir_(std::move(dir)), partial_(dir_ + ".partial"), rig_(rig)
{
	std::error_code ec;
	if (fs::exists(dir_) && !fs::is_empty(dir_) && !fs::exists(dir_ + "/" + kMarker))
		failInput(dir_, "exists and is not an earlier vlo-sim export; choose another --kitti-dir or remove it");
	fs::remove_all(partial_, ec);
	if (!fs::create_directories(seqDir(partial_) + "/image_0", ec) || !fs::create_directories(seqDir(partial_) + "/velodyne", ec) ||
		!fs::create_directories(partial_ + "/poses", ec))
		failInput(partial_, "cannot create directories: " + ec.message());
	AtomicOutputFile m(partial_ + "/" + kMarker);
	m.stream() << "Written by vlo-sim: " << description << "\n"
			   << "velodyne/*.bin are in the LiDAR frame; poses/00.txt are camera-0 poses (KITTI conventions);\n"
			   << "the simulator's <name>.gt.tum holds vehicle-frame poses (vehicle_T_lidar is not identity).\n";
	m.commit();
}

KittiExporter::~KittiExporter()
{
	if (committed_) return;
	std::error_code ec;
	fs::remove_all(partial_, ec);
}

void KittiExporter::write(const Frame& f)
{
	char name[32];
	std::snprintf(name, sizeof(name), "%06zu", f.index);
	const std::string seq = seqDir(partial_);
	if (f.has_image && !f.image.saveToFile(seq + "/image_0/" + name + ".png"))
		failInput(seq + "/image_0/" + name + ".png", "cannot write image");
	if (!f.has_scan) return;
	PointCloud reflectance = f.scan;  // KITTI's reflectance is in [0, 1], a timed scan's 8-bit
	if (f.scan.has_time)
		for (LidarPoint& p : reflectance) p.intensity /= 255.0f;
	io::writeKittiBin(seq + "/velodyne/" + name + ".bin", reflectance);
}

void KittiExporter::commit(const Trajectory& vehicle_gt)
{
	const std::string seq = seqDir(partial_);
	{
		AtomicOutputFile calib(seq + "/calib.txt");
		Eigen::Matrix<double, 3, 4> P = Eigen::Matrix<double, 3, 4>::Zero();
		P.leftCols<3>() = rig_.camera.K();
		Eigen::Matrix<double, 3, 4> P1 = P;  // a right camera 0.54 m away, as in KITTI (not rendered)
		P1(0, 3) = -rig_.camera.fx * 0.54;
		writeMatrixLine(calib.stream(), "P0", P);
		writeMatrixLine(calib.stream(), "P1", P1);
		writeMatrixLine(calib.stream(), "P2", P);
		writeMatrixLine(calib.stream(), "P3", P1);
		writeMatrixLine(calib.stream(), "Tr", cam0TVelo(rig_).matrix().topRows<3>());
		calib.commit();
	}
	{
		AtomicOutputFile times(seq + "/times.txt");
		char buf[32];
		for (const auto& p : vehicle_gt)
		{
			std::snprintf(buf, sizeof(buf), "%e\n", p.t);
			times.stream() << buf;
		}
		times.commit();
	}
	// Camera-0 motion: C_k = C_T_V * V_k * V_T_C.
	io::writeKittiPoses(partial_ + "/poses/00.txt", io::vehicleToCamera(vehicle_gt, rig_.vehicle_T_camera.inverse()));
	std::error_code ec;
	fs::remove_all(dir_, ec);
	fs::rename(partial_, dir_, ec);
	if (ec) failInput(dir_, "cannot move the export into place: " + ec.message());
	committed_ = true;
}
}  // namespace vlo::sim
