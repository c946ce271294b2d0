// The flocking order parameter of ARGoS's flocking example, for bench-argos-examples.sh: loop functions that write,
// after each step, the clock and the length of the foot-bots' mean heading (1: all alike) to flocking_order.txt.
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>
#include <fstream>

using namespace argos;

class CFlockingOrder : public CLoopFunctions {
public:
   void Init(TConfigurationNode&) override {
      m_cOut.open("flocking_order.txt");
   }

   void PostStep() override {
      Real fX = 0, fY = 0;
      UInt32 unN = 0;
      for(auto& tEntry : GetSpace().GetEntitiesByType("foot-bot")) {
         CFootBotEntity* pcBot = any_cast<CFootBotEntity*>(tEntry.second);
         CRadians cZ, cY, cX;
         pcBot->GetEmbodiedEntity().GetOriginAnchor().Orientation.ToEulerAngles(cZ, cY, cX);
         fX += Cos(cZ);
         fY += Sin(cZ);
         ++unN;
      }
      m_cOut << GetSpace().GetSimulationClock() << '\t' << Sqrt(fX * fX + fY * fY) / unN << '\n';
   }

   void Destroy() override {
      m_cOut.close();
   }

private:
   std::ofstream m_cOut;
};

REGISTER_LOOP_FUNCTIONS(CFlockingOrder, "flocking_order")
