# Mixed-effects models of a signstim study's results (docs/analysis.md, "Mixed models").
# Written by `signstim analyze` into REPORT/models/ next to the data it reads; rerun it as is:
#     Rscript REPORT/models/models.R                 # writes REPORT/models/models-rerun.csv
#     Rscript models.R [DATA_FOLDER [OUTPUT_CSV]]
# and compare the output with models-output.csv (the numbers the report shows).
#
#  - comprehension: logistic GLMM (lme4::glmer, binomial, logit link), one row per question:
#        correct ~ version + (1 | participant) + (1 | story)
#  - ratings: cumulative-link mixed model (ordinal::clmm, logit link, flexible thresholds),
#    one row per rating of a version:
#        rating ~ version + (1 | participant) + (1 | sentence)
# Each model is compared by a likelihood-ratio test with the model without `version`, and
# every pair of versions by a Wald z test of their difference (Holm-adjusted over the pairs).
# A positive estimate means more correct answers (log odds) or higher ratings (log cumulative
# odds of a higher rating) than the reference version. Warnings and messages of the fits
# (convergence, singular fits) are written out, not hidden.
# Needs R with the packages lme4 and ordinal (Debian: apt install r-base-core r-cran-lme4
# r-cran-ordinal; elsewhere install.packages(c("lme4", "ordinal"))).

versions <- c(@VERSIONS@)  # the study's versions, in its order
reference <- "@REFERENCE@"  # the level every estimate is relative to

args <- commandArgs(trailingOnly = TRUE)
script_file <- sub("^--file=", "", grep("^--file=", commandArgs(trailingOnly = FALSE), value = TRUE))
script_dir <- if (length(script_file) == 1) dirname(normalizePath(script_file)) else "."
data_dir <- if (length(args) >= 1) args[1] else script_dir
out_file <- if (length(args) >= 2) args[2] else file.path(data_dir, "models-rerun.csv")

missing_packages <- c("lme4", "ordinal")[!vapply(c("lme4", "ordinal"), requireNamespace, logical(1), quietly = TRUE)]
if (length(missing_packages) > 0) {
  message("signstim-models: missing R packages: ", paste(missing_packages, collapse = " "))
  quit(status = 3)
}
suppressPackageStartupMessages({
  library(lme4)
  library(ordinal)
})

rows <- list()
num <- function(x) ifelse(is.finite(x), sprintf("%.10g", x), "NA")
add <- function(model, section, term = "", estimate = NA, std_error = NA, statistic = NA, df = NA, p = NA,
                p_holm = NA, note = "") {
  rows[[length(rows) + 1]] <<- data.frame(model = model, section = section, term = term, estimate = num(estimate),
                                          std_error = num(std_error), statistic = num(statistic), df = num(df),
                                          p = num(p), p_holm = num(p_holm), note = note, stringsAsFactors = FALSE)
}

add("all", "info", "R", note = R.version.string)
add("all", "info", "lme4", note = as.character(packageVersion("lme4")))
add("all", "info", "ordinal", note = as.character(packageVersion("ordinal")))
add("all", "info", "reference", note = reference)

# Runs fit(), keeping every warning and message (convergence, singular fit) instead of
# printing them; an error becomes the result's `error`.
capture <- function(fit) {
  notes <- character(0)
  value <- withCallingHandlers(
    tryCatch(fit(), error = function(e) e),
    warning = function(w) {
      notes <<- c(notes, conditionMessage(w))
      invokeRestart("muffleWarning")
    },
    message = function(m) {
      notes <<- c(notes, sub("\n$", "", conditionMessage(m)))
      invokeRestart("muffleMessage")
    })
  list(value = value, notes = unique(notes))
}

# Effects of the versions relative to the reference (0 for it), their covariance, and every
# pair's Wald test, in the study's order of versions.
pairs_of <- function(model, beta, covariance, levels) {
  effect <- setNames(rep(0, length(levels)), levels)
  index <- setNames(rep(NA_integer_, length(levels)), levels)
  for (v in levels[levels != reference]) {
    name <- paste0("version", v)
    effect[v] <- beta[name]
    index[v] <- match(name, names(beta))
  }
  out <- NULL
  for (i in seq_along(levels)) for (j in seq_along(levels)) if (i < j) {
    a <- levels[i]; b <- levels[j]
    w <- rep(0, length(beta))
    if (!is.na(index[a])) w[index[a]] <- 1
    if (!is.na(index[b])) w[index[b]] <- w[index[b]] - 1
    se <- sqrt(drop(t(w) %*% covariance %*% w))
    d <- effect[a] - effect[b]
    out <- rbind(out, data.frame(term = paste(a, "-", b), estimate = d, se = se, z = d / se,
                                 p = 2 * pnorm(-abs(d / se)), stringsAsFactors = FALSE))
  }
  out$p_holm <- p.adjust(out$p, method = "holm")
  for (k in seq_len(nrow(out)))
    add(model, "pair", out$term[k], out$estimate[k], out$se[k], out$z[k], NA, out$p[k], out$p_holm[k])
}

prepare <- function(d) {
  levels <- versions[versions %in% unique(d$version)]
  if (!(reference %in% levels)) stop("the reference version '", reference, "' has no data")
  d$version <- relevel(factor(d$version, levels = levels), ref = reference)
  d$participant <- factor(d$participant)
  d
}

# ---- comprehension: logistic GLMM -----------------------------------------------------------
comprehension_file <- file.path(data_dir, "comprehension.csv")
if (file.exists(comprehension_file)) {
  d1 <- read.csv(comprehension_file, comment.char = "#", colClasses = "character")
  d1$correct <- as.integer(d1$correct)
  d1 <- prepare(d1)
  d1$story <- factor(d1$story)
  add("comprehension", "info", "formula", note = "correct ~ version + (1 | participant) + (1 | story)")
  add("comprehension", "info", "family", note = "binomial (logit), lme4::glmer, Laplace, bobyqa")
  add("comprehension", "info", "observations", nrow(d1))
  add("comprehension", "info", "participants", nlevels(d1$participant))
  add("comprehension", "info", "stories", nlevels(d1$story))
  control <- glmerControl(optimizer = "bobyqa")
  full <- capture(function() glmer(correct ~ version + (1 | participant) + (1 | story), data = d1,
                                   family = binomial, control = control))
  for (n in full$notes) add("comprehension", "warning", "fit", note = n)
  if (inherits(full$value, "error")) {
    add("comprehension", "error", note = conditionMessage(full$value))
  } else {
    m1 <- full$value
    for (n in m1@optinfo$conv$lme4$messages) add("comprehension", "warning", "convergence", note = n)
    if (isSingular(m1)) add("comprehension", "warning", "singular", note = "singular fit: a random-effect variance is estimated as (nearly) 0")
    cf <- summary(m1)$coefficients
    for (k in seq_len(nrow(cf)))
      add("comprehension", "fixed", sub("^version", "", rownames(cf)[k]), cf[k, 1], cf[k, 2], cf[k, 3], NA, cf[k, 4])
    vc <- as.data.frame(VarCorr(m1))
    for (k in seq_len(nrow(vc))) add("comprehension", "random", vc$grp[k], vc$sdcor[k], note = "sd (logit scale)")
    add("comprehension", "fit", "logLik", as.numeric(logLik(m1)))
    add("comprehension", "fit", "AIC", AIC(m1))
    pairs_of("comprehension", fixef(m1), as.matrix(vcov(m1)), levels(d1$version)[order(match(levels(d1$version), versions))])
    null <- capture(function() update(m1, . ~ . - version))
    for (n in null$notes) add("comprehension", "warning", "null model", note = n)
    if (inherits(null$value, "error")) {
      add("comprehension", "error", "likelihood ratio", note = conditionMessage(null$value))
    } else {
      lrt <- anova(null$value, m1)
      add("comprehension", "lrt", "version", NA, NA, lrt$Chisq[2], lrt$Df[2], lrt[["Pr(>Chisq)"]][2])
    }
  }
}

# ---- ratings: cumulative-link mixed model ---------------------------------------------------
ratings_file <- file.path(data_dir, "ratings.csv")
if (file.exists(ratings_file)) {
  d2 <- read.csv(ratings_file, comment.char = "#", colClasses = "character")
  d2$rating <- as.integer(d2$rating)
  d2 <- prepare(d2)
  d2$sentence <- factor(d2$sentence)
  # Thresholds only between the ratings given: a scale point nobody used has no threshold.
  d2$rating <- factor(d2$rating, levels = sort(unique(d2$rating)), ordered = TRUE)
  add("ratings", "info", "formula", note = "rating ~ version + (1 | participant) + (1 | sentence)")
  add("ratings", "info", "family", note = "cumulative logit, flexible thresholds, ordinal::clmm, Laplace")
  add("ratings", "info", "observations", nrow(d2))
  add("ratings", "info", "participants", nlevels(d2$participant))
  add("ratings", "info", "sentences", nlevels(d2$sentence))
  full <- capture(function() clmm(rating ~ version + (1 | participant) + (1 | sentence), data = d2, link = "logit",
                                  Hess = TRUE))
  for (n in full$notes) add("ratings", "warning", "fit", note = n)
  if (inherits(full$value, "error")) {
    add("ratings", "error", note = conditionMessage(full$value))
  } else {
    m2 <- full$value
    if (m2$optRes$convergence != 0)
      add("ratings", "warning", "convergence", note = paste("optimizer:", m2$optRes$message))
    s2 <- summary(m2)
    # ordinal's own rules of thumb (?clm.fit): a gradient above 1e-3 or a Hessian's condition
    # number above 1e4 makes estimates doubtful.
    if (max(abs(m2$gradient)) > 1e-3)
      add("ratings", "warning", "convergence", max(abs(m2$gradient)), note = "largest absolute gradient above 1e-3")
    if (!is.finite(s2$condHess) || s2$condHess > 1e4)
      add("ratings", "warning", "convergence", s2$condHess,
          note = "condition number of the Hessian above 1e4: the model may be ill defined")
    cf <- s2$coefficients
    nt <- length(m2$alpha)
    for (k in seq_len(nrow(cf)))
      add("ratings", if (k <= nt) "threshold" else "fixed", sub("^version", "", rownames(cf)[k]), cf[k, 1], cf[k, 2],
          cf[k, 3], NA, cf[k, 4])
    vc <- VarCorr(m2)
    for (g in names(vc)) add("ratings", "random", g, attr(vc[[g]], "stddev")[1], note = "sd (logit scale)")
    # clmm does not say so itself (glmer does): a random-effect SD at 0 is a singular fit.
    for (g in names(vc)) if (attr(vc[[g]], "stddev")[1] < 1e-4)
      add("ratings", "warning", "singular", note = paste0("singular fit: the SD of the ", g,
                                                          " intercepts is estimated as (nearly) 0"))
    add("ratings", "fit", "logLik", as.numeric(logLik(m2)))
    add("ratings", "fit", "AIC", AIC(m2))
    add("ratings", "fit", "condHess", s2$condHess)
    pairs_of("ratings", m2$beta, as.matrix(vcov(m2))[names(m2$beta), names(m2$beta), drop = FALSE],
             levels(d2$version)[order(match(levels(d2$version), versions))])
    null <- capture(function() clmm(rating ~ 1 + (1 | participant) + (1 | sentence), data = d2, link = "logit"))
    for (n in null$notes) add("ratings", "warning", "null model", note = n)
    if (inherits(null$value, "error")) {
      add("ratings", "error", "likelihood ratio", note = conditionMessage(null$value))
    } else {
      lrt <- anova(null$value, m2)
      add("ratings", "lrt", "version", NA, NA, lrt$LR.stat[2], lrt$df[2], lrt[["Pr(>Chisq)"]][2])
    }
  }
}

write.csv(do.call(rbind, rows), out_file, row.names = FALSE, na = "NA", fileEncoding = "UTF-8")
