#include <nsm/base/errors.h>
#include <nsm/output/field_output.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// Strain u_x and normal force E A(x) u_x from the displacement's
    /// gradient (x is the first coordinate, also in space-time).
    template <int dim>
    class AxialStrainAndForce : public dealii::DataPostprocessor<dim>
    {
    public:
      explicit AxialStrainAndForce(const BarModel &bar)
        : bar_(bar)
      {}

      void evaluate_scalar_field(const dealii::DataPostprocessorInputs::Scalar<dim> &inputs,
                                 std::vector<dealii::Vector<double>> &computed) const override
      {
        for (std::size_t q = 0; q < computed.size(); ++q)
          {
            const double strain = inputs.solution_gradients[q][0];
            const double x      = std::clamp(inputs.evaluation_points[q][0], 0.0, bar_.length());
            computed[q](0) = strain;
            computed[q](1) = bar_.young_modulus() * bar_.cross_section(x) * strain;
          }
      }

      std::vector<std::string> get_names() const override { return {"strain", "normal_force"}; }

      std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        return {dealii::DataComponentInterpretation::component_is_scalar,
                dealii::DataComponentInterpretation::component_is_scalar};
      }

      dealii::UpdateFlags get_needed_update_flags() const override
      {
        return dealii::update_gradients | dealii::update_quadrature_points;
      }

    private:
      const BarModel &bar_;
    };

    /// The displacement as a vector along x, (u, 0) in space-time, so that
    /// ParaView's Warp By Vector moves the bar along its axis.
    class AxialDisplacement : public dealii::DataPostprocessorVector<2>
    {
    public:
      AxialDisplacement()
        : dealii::DataPostprocessorVector<2>("displacement", dealii::update_values)
      {}

      void evaluate_scalar_field(const dealii::DataPostprocessorInputs::Scalar<2> &inputs,
                                 std::vector<dealii::Vector<double>>              &computed) const override
      {
        for (std::size_t q = 0; q < computed.size(); ++q)
          {
            computed[q](0) = inputs.solution_values[q];
            computed[q](1) = 0;
          }
      }
    };

    /// A VTU of `out`; with `omega_field`, its field datum (deal.II's TIME,
    /// which holds the frequency) is named Omega.
    template <int dim>
    std::string write_vtu(const std::string &path, const dealii::DataOut<dim> &out, const bool omega_field)
    {
      std::ostringstream text;
      out.write_vtu(text);
      std::string vtu = text.str();
      if (omega_field)
        if (const std::size_t at = vtu.find("Name=\"TIME\""); at != std::string::npos)
          vtu.replace(at, 11, "Name=\"Omega\"");
      return write_atomically(path, [&](std::ostream &s) { s << vtu; });
    }

    /// The VTU flags at `time`. The space-time field's cells are Lagrange
    /// quadrilaterals of the degree; the 1D snapshots' are each cell's p
    /// linear segments (deal.II 9.4 does not number the points of a Lagrange
    /// curve: its debug library refuses them, its release library writes
    /// cells whose points repeat).
    dealii::DataOutBase::VtkFlags vtk_flags(double time, bool higher_order_cells)
    {
      dealii::DataOutBase::VtkFlags flags;
      flags.time                     = time;
      flags.write_higher_order_cells = higher_order_cells;
      flags.print_date_and_time      = false;
      return flags;
    }

    std::string name(unsigned int index, const std::string &suffix)
    {
      return "field_" + std::to_string(index) + suffix;
    }

    /// Each DoF of the bar as (support abscissa, DoF), sorted by x.
    std::vector<std::pair<double, unsigned int>> dofs_by_x(const Discretisation &d)
    {
      std::vector<std::pair<double, unsigned int>> by_x;
      const std::vector<double>                    x = d.support_points();
      for (unsigned int i = 0; i < x.size(); ++i)
        by_x.emplace_back(x[i], i);
      std::sort(by_x.begin(), by_x.end());
      return by_x;
    }

    /// The (x, t) mesh: x cells as the bar's mesh, time cells so that the
    /// support points of FE_Q(p) in t number at least `samples`.
    void make_space_time_mesh(dealii::Triangulation<2> &mesh, const double duration, const Discretisation &d,
                              const unsigned int samples)
    {
      const unsigned int  p = d.fe().degree;
      std::vector<double> x_steps;
      {
        std::vector<std::pair<double, double>> cells;
        for (const auto &cell : d.dof_handler().active_cell_iterators())
          cells.emplace_back(cell->vertex(0)[0], cell->vertex(1)[0]);
        std::sort(cells.begin(), cells.end());
        for (const auto &[a, b] : cells)
          x_steps.push_back(b - a);
      }
      const unsigned int        time_cells = (samples + p - 1) / p;
      const std::vector<double> t_steps(time_cells, duration / time_cells);
      dealii::GridGenerator::subdivided_hyper_rectangle(mesh, {x_steps, t_steps}, dealii::Point<2>(0, 0),
                                                        dealii::Point<2>(d.bar().length(), duration));
    }

    /// The space-time field on the 2D mesh of (x, t), FE_Q(p) in both, values
    /// interpolated at the support points (exact in x: the 2D and 1D support
    /// points coincide).
    /// The VTK files' time unit: the period (their time is t / T) or 1.
    double time_unit(const PeriodicField &field, const bool over_period)
    {
      return over_period ? field.period() : 1.0;
    }

    std::string write_space_time(const std::string    &directory,
                                 unsigned int          index,
                                 const PeriodicField  &field,
                                 const Discretisation &d,
                                 unsigned int          samples,
                                 const double          unit)
    {
      const unsigned int       p = d.fe().degree;
      dealii::Triangulation<2> mesh;
      make_space_time_mesh(mesh, field.period() / unit, d, samples);
      const dealii::FE_Q<2> fe(p);
      dealii::DoFHandler<2> dofs(mesh);
      dofs.distribute_dofs(fe);

      // 1D DoF at each support abscissa.
      const std::vector<std::pair<double, unsigned int>> by_x = dofs_by_x(d);
      const auto dof_at = [&](double x) {
        auto it = std::lower_bound(by_x.begin(), by_x.end(), std::make_pair(x - 1e-12 * d.bar().length(), 0u));
        if (it == by_x.end() || std::abs(it->first - x) > 1e-9 * d.bar().length())
          throw NumericalError("space-time mesh: no 1D support point at x = " + std::to_string(x));
        return it->second;
      };

      std::vector<dealii::Point<2>> points(dofs.n_dofs());
      dealii::DoFTools::map_dofs_to_support_points(dealii::MappingQ1<2>(), dofs, points);
      dealii::Vector<double> u(dofs.n_dofs()), v(dofs.n_dofs());
      for (unsigned int i = 0; i < dofs.n_dofs(); ++i)
        {
          const unsigned int dof = dof_at(points[i][0]);
          u[i] = field.displacement(dof, points[i][1] * unit);
          v[i] = field.velocity(dof, points[i][1] * unit);
        }

      const AxialStrainAndForce<2> derived(d.bar());
      dealii::DataOut<2>           out;
      out.attach_dof_handler(dofs);
      const AxialDisplacement axial;
      out.add_data_vector(u, axial);
      out.add_data_vector(u, "axial_displacement"); // the same u as a scalar: coloured with its sign
      out.add_data_vector(v, "velocity");
      out.add_data_vector(u, derived);
      out.build_patches(p);
      out.set_flags(vtk_flags(field.omega(), true));
      return write_vtu(directory + "/" + name(index, ".vtu"), out, true);
    }

    /// 1D snapshots over one period and their .pvd time series.
    std::vector<std::string> write_snapshots(const std::string    &directory,
                                             unsigned int          index,
                                             const PeriodicField  &field,
                                             const Discretisation &d,
                                             unsigned int          samples,
                                             const double          unit)
    {
      const std::string folder = name(index, "_snapshots");
      std::filesystem::create_directories(directory + "/" + folder);
      const AxialStrainAndForce<1>                derived(d.bar());
      std::vector<std::pair<double, std::string>> series;
      for (unsigned int j = 0; j < samples; ++j)
        {
          const double                 t = field.period() * j / samples;
          const dealii::Vector<double> u = field.displacement(t), v = field.velocity(t);
          dealii::DataOut<1>           out;
          out.attach_dof_handler(d.dof_handler());
          // In 1D a vector has one component: VTK pads it to (u, 0, 0).
          out.add_data_vector(u, std::vector<std::string>{"displacement"}, dealii::DataOut<1>::type_dof_data,
                              {dealii::DataComponentInterpretation::component_is_part_of_vector});
          out.add_data_vector(u, "axial_displacement");
          out.add_data_vector(v, "velocity");
          out.add_data_vector(u, derived);
          out.build_patches(d.fe().degree);
          out.set_flags(vtk_flags(t / unit, false));
          std::ostringstream file;
          file << folder << "/snapshot_" << std::setw(4) << std::setfill('0') << j << ".vtu";
          write_vtu(directory + "/" + file.str(), out, false);
          series.emplace_back(t / unit, file.str());
        }
      return {write_atomically(directory + "/" + name(index, "_snapshots.pvd"),
                         [&](std::ostream &s) { dealii::DataOutBase::write_pvd_record(s, series); }),
              directory + "/" + folder + "/ (" + std::to_string(samples) + " snapshots)"};
    }

    /// The contact end over one period, at `n` instants.
    CsvTable tip_table(const unsigned int index, const PeriodicField &field, const Discretisation &d,
                       const unsigned int n)
    {
      CsvTable tip{name(index, "_tip.csv"), {"t", "contact_displacement", "contact_velocity", "contact_force"}, {}};
      for (unsigned int j = 0; j < n; ++j)
        {
          const double t = field.period() * j / n;
          tip.rows.push_back({t, field.contact_displacement(t), field.velocity(d.contact_dof(), t),
                              field.contact_force(t)});
        }
      return tip;
    }

    CsvTable harmonics_table(const unsigned int index, const PeriodicField &field)
    {
      CsvTable                   harmonics{name(index, "_harmonics.csv"), {"k", "is_sine", "force", "displacement"}, {}};
      const FourierCoefficients &c = field.coefficients();
      for (std::size_t i = 0; i < c.order.size(); ++i)
        harmonics.rows.push_back({double(c.order[i]), double(c.is_sine[i]), c.force[i], c.displacement[i]});
      return harmonics;
    }

    /// The profile at t = 0 at every DoF, sorted by x.
    CsvTable initial_table(const unsigned int index, const PeriodicField &field, const Discretisation &d)
    {
      CsvTable initial{name(index, "_initial.csv"), {"x", "displacement", "velocity"}, {}};
      const dealii::Vector<double> u0 = field.displacement(0.0), v0 = field.velocity(0.0);
      for (const auto &[x, dof] : dofs_by_x(d))
        initial.rows.push_back({x, u0[dof], v0[dof]});
      return initial;
    }

    /// u(x, t) for the colour map: n + 1 instants, at most ~200 abscissae
    /// (and always the contact end).
    CsvTable space_time_table(const unsigned int index, const PeriodicField &field, const Discretisation &d,
                              const unsigned int n)
    {
      const std::vector<std::pair<double, unsigned int>> by_x   = dofs_by_x(d);
      const std::size_t                                  stride = std::max<std::size_t>(1, by_x.size() / 200);
      CsvTable grid{name(index, "_spacetime.csv"), {"t", "x", "displacement"}, {}};
      for (unsigned int j = 0; j <= n; ++j)
        {
          const double                 t = field.period() * j / n;
          const dealii::Vector<double> u = field.displacement(t);
          for (std::size_t i = 0; i < by_x.size(); i += stride)
            grid.rows.push_back({t, by_x[i].first, u[by_x[i].second]});
          if ((by_x.size() - 1) % stride)
            grid.rows.push_back({t, by_x.back().first, u[by_x.back().second]});
        }
      return grid;
    }
  } // namespace

  std::vector<std::string> write_field(const std::string        &directory,
                                       unsigned int              index,
                                       const PeriodicField      &field,
                                       const Discretisation     &d,
                                       const FieldOutputOptions &options)
  {
    const unsigned int       n = options.time_samples;
    std::vector<std::string> files{write_csv(directory, tip_table(index, field, d, n)),
                                   write_csv(directory, harmonics_table(index, field)),
                                   write_csv(directory, initial_table(index, field, d))};
    if (options.plots)
      files.push_back(write_csv(directory, space_time_table(index, field, d, n)));
    if (options.vtk)
      {
        const double unit = time_unit(field, options.vtk_time_over_period);
        files.push_back(write_space_time(directory, index, field, d, n, unit));
        for (std::string &f : write_snapshots(directory, index, field, d, n, unit))
          files.push_back(std::move(f));
      }
    return files;
  }

  std::vector<std::string> write_field_collection(const std::string                &directory,
                                                  const std::vector<PeriodicField> &fields,
                                                  bool                              vtk)
  {
    CsvTable table{"fields.csv",
                   {"index", "Omega", "segment", "energy", "branch", "resonance_mode", "resonance_harmonic"},
                   {}};
    std::vector<std::pair<double, std::string>> records;
    for (std::size_t i = 0; i < fields.size(); ++i)
      {
        const BackbonePoint &p = fields[i].point();
        table.rows.push_back({double(i), p.omega, double(p.segment), p.measures.energy,
                              std::string(branch_name(p.branch)),
                              double(p.resonance.mode), double(p.resonance.harmonic)});
        records.emplace_back(p.omega, name(i, ".vtu"));
      }
    std::vector<std::string> files{write_csv(directory, table)};
    if (vtk)
      files.push_back(write_atomically(directory + "/fields.pvd", [&](std::ostream &s) {
        dealii::DataOutBase::write_pvd_record(s, records);
      }));
    return files;
  }
} // namespace nsm
