// Finite-element discretisation of the bar: mesh (uniform, graded or
// adaptively refined towards x = L), FE_Q(p), stiffness K and mass M.
#pragma once

#include <nsm/model/bar_model.h>
#include <nsm/scene/discretisation_parameters.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace nsm
{
  class Discretisation
  {
  public:
    Discretisation(const BarModel &bar, const DiscretisationParameters &params);

    /// The same mesh with another FE degree (the adaptive error estimate
    /// compares degrees p and p + 1), each cell split `halvings` times (the
    /// band check's reference has every cell halved once).
    Discretisation(const Discretisation &other, unsigned int degree, unsigned int halvings = 0);

    /// Refines the cells with the largest indicators (a fraction of them)
    /// and reassembles.
    void refine(const dealii::Vector<float> &indicators, double fraction);

    /// Kelly jump indicator of a field, squared per cell.
    dealii::Vector<float> kelly_indicators(const dealii::Vector<double> &field) const;

    const dealii::SparseMatrix<double> &stiffness() const { return stiffness_; }
    const dealii::SparseMatrix<double> &mass() const { return mass_; }
    const dealii::DoFHandler<1>        &dof_handler() const { return dof_handler_; }
    const dealii::FE_Q<1>              &fe() const { return fe_; }
    const BarModel                     &bar() const { return bar_; }

    unsigned int n_dofs() const { return dof_handler_.n_dofs(); }
    unsigned int n_cells() const;
    unsigned int contact_dof() const { return contact_dof_; }
    unsigned int clamped_dof() const { return clamped_dof_; }
    double       min_cell_size() const;
    double       max_cell_size() const;

    /// DoFs that move in the clamped-free problem (all but the clamped one),
    /// and without the contact DoF too for the clamped-clamped problem.
    std::vector<unsigned int> free_dofs(bool clamp_contact_end) const;

    /// Positions of the DoFs' support points.
    std::vector<double> support_points() const;
    /// The nodal loads of a unit force per unit length along the whole bar,
    /// f_i = int_0^L N_i dx (0 on the clamped DoF): a uniform drive's shape.
    dealii::Vector<double> unit_load() const;

  private:
    void make_mesh(const DiscretisationParameters &params);
    void setup_and_assemble();

    const BarModel              &bar_;
    unsigned int                 quadrature_points_;
    ContactMass                  contact_mass_;
    dealii::Triangulation<1>     triangulation_;
    dealii::FE_Q<1>              fe_;
    dealii::DoFHandler<1>        dof_handler_;
    dealii::SparsityPattern      sparsity_;
    dealii::SparseMatrix<double> stiffness_;
    dealii::SparseMatrix<double> mass_;
    unsigned int                 contact_dof_ = 0;
    unsigned int                 clamped_dof_ = 0;
  };
} // namespace nsm
