#include "background_pool.h"

#include <QThread>
#include <QThreadPool>
#include <algorithm>

namespace pat::ui {

QThreadPool* background_pool() {
  static QThreadPool* pool = [] {
    auto* p = new QThreadPool;  // never deleted: runners' destructors may wait on it at exit
    p->setMaxThreadCount(std::max(2, QThread::idealThreadCount()));
    return p;
  }();
  return pool;
}

}  // namespace pat::ui
