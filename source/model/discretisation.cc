#include <nsm/model/discretisation.h>
#include <nsm/model/mass_redistribution.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/numerics/error_estimator.h>

#include <algorithm>
#include <cmath>

namespace nsm
{
  Discretisation::Discretisation(const BarModel                &bar,
                                 const DiscretisationParameters &params)
    : bar_(bar)
    , quadrature_points_(params.quadrature_points != 0 ?
                           params.quadrature_points :
                           params.degree + 2)
    , contact_mass_(params.contact_mass)
    , fe_(params.degree)
    , dof_handler_(triangulation_)
  {
    make_mesh(params);
    setup_and_assemble();
  }

  Discretisation::Discretisation(const Discretisation &other,
                                 const unsigned int    degree,
                                 const unsigned int    halvings)
    : bar_(other.bar_)
    , quadrature_points_(other.quadrature_points_ + degree - other.fe_.degree)
    , contact_mass_(other.contact_mass_)
    , fe_(degree)
    , dof_handler_(triangulation_)
  {
    triangulation_.copy_triangulation(other.triangulation_);
    triangulation_.refine_global(halvings);
    setup_and_assemble();
  }

  void Discretisation::make_mesh(const DiscretisationParameters &params)
  {
    // Cell sizes: uniform, except the last `Layers` cells, which shrink by
    // `Ratio` from one to the next towards the contact end.
    std::vector<double> sizes(params.cells, 1.0);
    if (params.refinement == Refinement::graded)
      {
        const unsigned int first = params.cells - params.graded_layers;
        for (unsigned int i = first; i < params.cells; ++i)
          sizes[i] = std::pow(params.graded_ratio, i - first + 1);
      }
    double total = 0;
    for (const double s : sizes)
      total += s;
    for (double &s : sizes)
      s *= bar_.length() / total;
    // The vertices are the sums of the sizes from 0: the last lies within
    // round-off (cells eps relative) of L, where deal.II's debug library
    // requires the end point it is given to be their sum.
    double end = 0;
    for (const double s : sizes)
      end += s;
    dealii::GridGenerator::subdivided_hyper_rectangle(
      triangulation_,
      {sizes},
      dealii::Point<1>(0.0),
      dealii::Point<1>(end),
      /*colorize=*/true);
  }

  void Discretisation::setup_and_assemble()
  {
    dof_handler_.distribute_dofs(fe_);
    // Band ordering: the spectrum uses banded LAPACK on these matrices.
    dealii::DoFRenumbering::Cuthill_McKee(dof_handler_);
    const unsigned int n = dof_handler_.n_dofs();

    dealii::DynamicSparsityPattern dsp(n, n);
    dealii::DoFTools::make_sparsity_pattern(dof_handler_, dsp);
    sparsity_.copy_from(dsp);
    stiffness_.reinit(sparsity_);
    mass_.reinit(sparsity_);

    const dealii::QGauss<1> quadrature(quadrature_points_);
    dealii::FEValues<1>     fe_values(fe_,
                                  quadrature,
                                  dealii::update_values |
                                    dealii::update_gradients |
                                    dealii::update_quadrature_points |
                                    dealii::update_JxW_values);
    const unsigned int      dofs_per_cell = fe_.n_dofs_per_cell();
    dealii::FullMatrix<double> cell_k(dofs_per_cell, dofs_per_cell);
    dealii::FullMatrix<double> cell_m(dofs_per_cell, dofs_per_cell);
    std::vector<dealii::types::global_dof_index> indices(dofs_per_cell);

    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell_k = 0;
        cell_m = 0;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            // BarModel throws if A <= 0 at a quadrature point.
            const double area = bar_.cross_section(fe_values.quadrature_point(q)[0]);
            const double ea   = bar_.young_modulus() * area * fe_values.JxW(q);
            const double rhoa = bar_.density() * area * fe_values.JxW(q);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              for (unsigned int j = 0; j < dofs_per_cell; ++j)
                {
                  cell_k(i, j) += ea * fe_values.shape_grad(i, q)[0] *
                                  fe_values.shape_grad(j, q)[0];
                  cell_m(i, j) += rhoa * fe_values.shape_value(i, q) *
                                  fe_values.shape_value(j, q);
                }
          }
        cell->get_dof_indices(indices);
        stiffness_.add(indices, cell_k);
        mass_.add(indices, cell_m);

        for (unsigned int v = 0; v < 2; ++v)
          {
            const double x = cell->vertex(v)[0];
            bar_.cross_section(x); // checks A > 0 at the nodes too
            if (cell->at_boundary(v) && cell->face(v)->boundary_id() == 0)
              clamped_dof_ = cell->vertex_dof_index(v, 0);
            if (cell->at_boundary(v) && cell->face(v)->boundary_id() == 1)
              contact_dof_ = cell->vertex_dof_index(v, 0);
          }
      }

    // Clamping: the clamped row and column of K reduce to a positive diagonal
    // and M's vanish there, so K - w^2 M stays regular at every w and the
    // clamped DoF adds no spurious eigenvalue.
    const double k_diagonal = stiffness_.diag_element(clamped_dof_);
    for (auto it = sparsity_.begin(clamped_dof_); it != sparsity_.end(clamped_dof_); ++it)
      {
        const unsigned int j = it->column();
        stiffness_.set(clamped_dof_, j, 0.0);
        stiffness_.set(j, clamped_dof_, 0.0);
        mass_.set(clamped_dof_, j, 0.0);
        mass_.set(j, clamped_dof_, 0.0);
      }
    stiffness_.set(clamped_dof_, clamped_dof_, k_diagonal);
    if (contact_mass_ == ContactMass::redistributed)
      redistribute_contact_mass(mass_, contact_dof_);
  }

  dealii::Vector<double> Discretisation::unit_load() const
  {
    const dealii::QGauss<1>  quadrature(quadrature_points_);
    dealii::FEValues<1>      fe_values(fe_, quadrature, dealii::update_values | dealii::update_JxW_values);
    std::vector<dealii::types::global_dof_index> indices(fe_.n_dofs_per_cell());
    dealii::Vector<double>   load(n_dofs());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell->get_dof_indices(indices);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          for (unsigned int i = 0; i < indices.size(); ++i)
            load[indices[i]] += fe_values.shape_value(i, q) * fe_values.JxW(q);
      }
    load[clamped_dof_] = 0;
    return load;
  }

  void Discretisation::refine(const dealii::Vector<float> &indicators,
                              const double                 fraction)
  {
    // At least one cell, or small meshes would never refine.
    const double at_least_one = (1 + 1e-9) / triangulation_.n_active_cells();
    dealii::GridRefinement::refine_and_coarsen_fixed_number(
      triangulation_, indicators, std::max(fraction, at_least_one), 0.0);
    triangulation_.execute_coarsening_and_refinement();
    setup_and_assemble();
  }

  dealii::Vector<float>
  Discretisation::kelly_indicators(const dealii::Vector<double> &field) const
  {
    dealii::Vector<float> indicators(triangulation_.n_active_cells());
    dealii::KellyErrorEstimator<1>::estimate(
      dof_handler_,
      dealii::QGauss<0>(1),
      std::map<dealii::types::boundary_id, const dealii::Function<1> *>(),
      field,
      indicators);
    for (float &e : indicators)
      e *= e;
    return indicators;
  }

  unsigned int Discretisation::n_cells() const
  {
    return triangulation_.n_active_cells();
  }

  double Discretisation::min_cell_size() const
  {
    double h = bar_.length();
    for (const auto &cell : triangulation_.active_cell_iterators())
      h = std::min(h, cell->diameter());
    return h;
  }

  double Discretisation::max_cell_size() const
  {
    double h = 0;
    for (const auto &cell : triangulation_.active_cell_iterators())
      h = std::max(h, cell->diameter());
    return h;
  }

  std::vector<unsigned int>
  Discretisation::free_dofs(const bool clamp_contact_end) const
  {
    std::vector<unsigned int> dofs;
    for (unsigned int i = 0; i < n_dofs(); ++i)
      if (i != clamped_dof_ && !(clamp_contact_end && i == contact_dof_))
        dofs.push_back(i);
    return dofs;
  }

  std::vector<double> Discretisation::support_points() const
  {
    std::vector<double> x(n_dofs());
    const std::vector<dealii::Point<1>> &unit = fe_.get_unit_support_points();
    std::vector<dealii::types::global_dof_index> indices(fe_.n_dofs_per_cell());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        cell->get_dof_indices(indices);
        const double x0 = cell->vertex(0)[0], x1 = cell->vertex(1)[0];
        for (unsigned int i = 0; i < indices.size(); ++i)
          x[indices[i]] = x0 + unit[i][0] * (x1 - x0);
      }
    return x;
  }
} // namespace nsm
