// nsm-bar SCENE.prm: argument handling only; the work is in run_scene().
#include <nsm/pipeline.h>
#include <nsm/scene.h>

#include <deal.II/base/parameter_handler.h>

#include <iostream>
#include <string>

int main(int argc, char **argv)
{
  const std::string usage =
    "usage: nsm-bar [SCENE.prm]   (default: " NSM_DEFAULT_SCENE ")\n"
    "       nsm-bar --print-parameters\n";
  if (argc > 2)
    {
      std::cerr << usage;
      return 2;
    }
  const std::string argument = argc == 2 ? argv[1] : NSM_DEFAULT_SCENE;
  if (argument == "--help" || argument == "-h")
    {
      std::cout << usage
                << "exit codes: 0 done, 2 bad input, 3 numerical failure, 4 other error, 5 a file could "
                   "not be written whole\n";
      return 0;
    }
  if (argument == "--print-parameters")
    {
      dealii::ParameterHandler prm;
      nsm::Scene::declare(prm);
      prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
      return 0;
    }
  try
    {
      const nsm::Scene scene = nsm::Scene::from_file(argument);
      std::cout << "nsm-bar: scene " << argument << '\n';
      nsm::print_report(nsm::run_scene(scene), std::cout);
      return 0;
    }
  catch (const nsm::InputError &e)
    {
      std::cerr << "nsm-bar: input error: " << e.what() << '\n';
      return 2;
    }
  catch (const nsm::OutputError &e)
    {
      std::cerr << "nsm-bar: output error: " << e.what() << '\n';
      return 5;
    }
  catch (const nsm::NumericalError &e)
    {
      std::cerr << "nsm-bar: numerical failure: " << e.what() << '\n';
      return 3;
    }
  catch (const std::exception &e)
    {
      std::cerr << "nsm-bar: error: " << e.what() << '\n';
      return 4;
    }
  catch (const char *message) // NOX throws these
    {
      std::cerr << "nsm-bar: numerical failure: " << message << '\n';
      return 3;
    }
  catch (...)
    {
      std::cerr << "nsm-bar: error: an exception of unknown type\n";
      return 4;
    }
}
