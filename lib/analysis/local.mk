# lib/analysis -- the analyses: the two exact routes to a mode's wrench
# cone, modes and feasibility, classification, stability sets, pushing
# regions, insertion plans.

lib_libwc_la_SOURCES += \
	lib/analysis/wrench.c \
	lib/analysis/direct.c \
	lib/analysis/direct3.c \
	lib/analysis/zrows3.c \
	lib/analysis/paper.c \
	lib/analysis/trace.c \
	lib/analysis/kinematics.c \
	lib/analysis/modeswalk.c \
	lib/analysis/push.c \
	lib/analysis/stabmodel.c \
	lib/analysis/facesys.c \
	lib/analysis/classify.c \
	lib/analysis/cellset.c \
	lib/analysis/cellbits.c \
	lib/analysis/stability.c \
	lib/analysis/setcert.c \
	lib/analysis/stabcert.c \
	lib/analysis/plancert.c \
	lib/analysis/planstr.c \
	lib/analysis/plancones.c \
	lib/analysis/plangraph.c \
	lib/analysis/plan.c \
	lib/analysis/robust.c \
	lib/analysis/plansweep.c \
	lib/analysis/sweep.c
wcanalysisdir = $(pkgincludedir)/analysis
wcanalysis_HEADERS = \
	lib/analysis/wrench.h \
	lib/analysis/kinematics.h \
	lib/analysis/push.h \
	lib/analysis/stability.h \
	lib/analysis/plan.h \
	lib/analysis/sweep.h
noinst_HEADERS += \
	lib/analysis/direct3.h \
	lib/analysis/zrows3.h \
	lib/analysis/planparts.h \
	lib/analysis/cellset.h \
	lib/analysis/modeswalk.h \
	lib/analysis/stabmodel.h \
	lib/analysis/facesys.h \
	lib/analysis/setcert.h \
	lib/analysis/stabcert.h \
	lib/analysis/plancert.h
