//! The job files users copy: `sweeps/k8s-indexed-job.yaml` is valid against the Kubernetes batch/v1 Job
//! schema (a trimmed schema in `tests/data/`, checked by the small JSON-Schema validator below), and the CI
//! pipelines of `examples/ci/` are valid YAML that run the steps `.ci/run` exercises (`steps.sh selftest`).
//! The Slurm script is run on a real (single-node) Slurm by `tests/slurm_cluster.rs` (ignored by default).

use std::path::Path;

use serde_json::Value;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn read(rel: &str) -> String {
    std::fs::read_to_string(Path::new(ROOT).join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

/// Every YAML document of `text`, as JSON values.
fn yaml_documents(text: &str, file: &str) -> Vec<Value> {
    use serde::Deserialize;
    serde_yaml::Deserializer::from_str(text)
        .map(|d| Value::deserialize(d).unwrap_or_else(|e| panic!("{file}: {e}")))
        .collect()
}

fn type_ok(t: &str, v: &Value) -> bool {
    match t {
        "object" => v.is_object(),
        "array" => v.is_array(),
        "string" => v.is_string(),
        "boolean" => v.is_boolean(),
        "integer" => v.is_i64() || v.is_u64(),
        "number" => v.is_number(),
        "null" => v.is_null(),
        _ => panic!("schema type '{t}' not supported"),
    }
}

/// Validates `v` against `schema` (the keywords the trimmed schema uses); the problems found, each with
/// its JSON path.
fn validate(v: &Value, schema: &Value, root: &Value, path: &str, errors: &mut Vec<String>) {
    if let Some(r) = schema.get("$ref").and_then(Value::as_str) {
        let name = r.strip_prefix("#/definitions/").expect("local $ref");
        return validate(v, &root["definitions"][name], root, path, errors);
    }
    for k in schema.as_object().expect("schema object").keys() {
        assert!(
            [
                "$schema",
                "$comment",
                "type",
                "properties",
                "additionalProperties",
                "required",
                "enum",
                "items",
                "minimum",
                "definitions"
            ]
            .contains(&k.as_str()),
            "schema keyword '{k}' not supported"
        );
    }
    if let Some(t) = schema.get("type") {
        let ok = match t {
            Value::String(t) => type_ok(t, v),
            Value::Array(ts) => ts.iter().any(|t| type_ok(t.as_str().unwrap(), v)),
            _ => panic!("bad type"),
        };
        if !ok {
            errors.push(format!("{path}: {v} is not of type {t}"));
            return;
        }
    }
    if let Some(e) = schema.get("enum").and_then(Value::as_array)
        && !e.contains(v)
    {
        errors.push(format!("{path}: {v} is not one of {e:?}"));
    }
    if let (Some(m), Some(x)) = (schema.get("minimum").and_then(Value::as_f64), v.as_f64())
        && x < m
    {
        errors.push(format!("{path}: {x} is below the minimum {m}"));
    }
    if let Some(o) = v.as_object() {
        for r in schema
            .get("required")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
        {
            if !o.contains_key(r.as_str().unwrap()) {
                errors.push(format!("{path}: the required field {r} is missing"));
            }
        }
        let props = schema.get("properties").and_then(Value::as_object);
        for (k, x) in o {
            let p = format!("{path}.{k}");
            match (
                props.and_then(|ps| ps.get(k)),
                schema.get("additionalProperties"),
            ) {
                (Some(s), _) => validate(x, s, root, &p, errors),
                (None, Some(Value::Bool(false))) => {
                    errors.push(format!("{p}: unknown field (not in the schema)"))
                }
                (None, Some(s)) if s.is_object() => validate(x, s, root, &p, errors),
                _ => {}
            }
        }
    }
    if let (Some(a), Some(items)) = (v.as_array(), schema.get("items")) {
        for (i, x) in a.iter().enumerate() {
            validate(x, items, root, &format!("{path}[{i}]"), errors);
        }
    }
}

fn job_schema() -> Value {
    serde_json::from_str(&read("tests/data/k8s-job-batch-v1.trimmed.schema.json")).unwrap()
}

fn job_errors(doc: &Value) -> Vec<String> {
    let schema = job_schema();
    let mut errors = Vec::new();
    validate(doc, &schema, &schema, "$", &mut errors);
    errors
}

#[test]
fn the_kubernetes_manifest_is_a_valid_indexed_job_and_merge_job() {
    let file = "sweeps/k8s-indexed-job.yaml";
    let docs = yaml_documents(&read(file), file);
    assert_eq!(docs.len(), 2, "{file}: the sweep Job and the merge Job");
    for d in &docs {
        let errors = job_errors(d);
        assert!(errors.is_empty(), "{file}: {errors:#?}");
    }
    // The sweep Job: Indexed, SLAMTOOL_SHARD_COUNT = completions (the tool cannot see completions).
    let spec = &docs[0]["spec"];
    assert_eq!(spec["completionMode"], "Indexed");
    let container = &spec["template"]["spec"]["containers"][0];
    let count = container["env"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["name"] == "SLAMTOOL_SHARD_COUNT")
        .expect("SLAMTOOL_SHARD_COUNT")["value"]
        .as_str()
        .unwrap()
        .to_string();
    assert_eq!(count, spec["completions"].to_string());
    let merge = docs[1]["spec"]["template"]["spec"]["containers"][0]["args"][0]
        .as_str()
        .unwrap();
    assert!(merge.starts_with("slamtool merge /data/"), "{merge}");
}

#[test]
fn the_validator_refuses_what_kubernetes_would() {
    // The validator is only worth something if it catches the mistakes a hand-edited manifest has.
    let file = "sweeps/k8s-indexed-job.yaml";
    let good = yaml_documents(&read(file), file).remove(0);
    let mutate = |f: &dyn Fn(&mut Value)| {
        let mut d = good.clone();
        f(&mut d);
        job_errors(&d)
    };
    let e = mutate(&|d| d["spec"]["completionMode"] = "indexed".into());
    assert!(e.iter().any(|e| e.contains("completionMode")), "{e:?}");
    let e = mutate(&|d| d["spec"]["template"]["spec"]["restartPolicy"] = "Sometimes".into());
    assert!(e.iter().any(|e| e.contains("restartPolicy")), "{e:?}");
    let e = mutate(&|d| d["spec"]["completion"] = 4.into());
    assert!(
        e.iter()
            .any(|e| e.contains("spec.completion: unknown field")),
        "{e:?}"
    );
    let e = mutate(&|d| d["spec"]["parallelism"] = "4".into());
    assert!(e.iter().any(|e| e.contains("parallelism")), "{e:?}");
    let e =
        mutate(&|d| d["spec"]["template"]["spec"]["containers"][0]["env"][0]["value"] = 4.into());
    assert!(e.iter().any(|e| e.contains("env[0].value")), "{e:?}");
    let e = mutate(&|d| {
        d["spec"].as_object_mut().unwrap().remove("template");
    });
    assert!(e.iter().any(|e| e.contains("template")), "{e:?}");
}

#[test]
fn the_ci_pipelines_are_valid_yaml_and_run_the_tested_steps() {
    for file in [
        "examples/ci/github-actions.yml",
        "examples/ci/gitlab-ci.yml",
        "examples/ci/github-pr-diff.yml",
    ] {
        let text = read(file);
        let docs = yaml_documents(&text, file);
        assert_eq!(docs.len(), 1, "{file}");
        assert!(
            text.contains("ci/steps.sh assess"),
            "{file} does not run the assess step"
        );
        assert!(
            text.contains("ci/steps.sh diff"),
            "{file} does not run the diff step"
        );
        assert!(
            text.contains("--rev \"$SLAMTOOL_REV\""),
            "{file}: slamtool is not pinned"
        );
    }
    let gh = yaml_documents(&read("examples/ci/github-actions.yml"), "gh").remove(0);
    let steps = gh["jobs"]["assess"]["steps"].as_array().unwrap();
    let upload = steps
        .iter()
        .find(|s| {
            s["uses"]
                .as_str()
                .is_some_and(|u| u.starts_with("actions/upload-artifact"))
        })
        .expect("an upload step");
    assert_eq!(
        upload["if"], "always()",
        "the report must be published when the limits fail"
    );
    let paths = upload["with"]["path"].as_str().unwrap();
    for f in ["report.pdf", "summary.json", "*.csv"] {
        assert!(paths.contains(f), "{f} is not published");
    }
    let gl = yaml_documents(&read("examples/ci/gitlab-ci.yml"), "gl").remove(0);
    assert_eq!(gl["slamming"]["artifacts"]["when"], "always");
    // .ci/run exercises the same steps.
    assert!(read(".ci/run").contains("examples/ci/steps.sh selftest"));
}
